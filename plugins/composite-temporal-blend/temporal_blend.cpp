// composite.temporal_blend: a time series (Blue Marble Next Generation's twelve monthly mosaics; any rasters
// with dates) as one layer at the scene's date, the two bracketing steps blended linearly in time, in geometry
// and imagery alike (seed 000 sections 1.1 and 6, time-varying data; digest 000 section 6).
#include <memory>

#include <strata/node.hpp>
#include <strata/node_type.hpp>
#include <strata/plugin.hpp>

#include "temporal_blend_layer.hpp"
#include "temporal_series.hpp"

namespace strata::composite {
namespace {

std::vector<const Layer*> stepLayers(const NodeSetup& setup) {
  std::vector<const Layer*> steps;
  for (Node* node : setup.inputList("steps")) steps.push_back(node->layer());
  for (const Layer* step : steps)
    if (step->kind() != steps.front()->kind())
      throw Error(setup.where, "the steps are of different kinds (" + std::string(toString(steps.front()->kind())) +
                                   " and " + toString(step->kind()) + "), which cannot be blended",
                  "give steps of one kind: heights with heights, colours with colours");
  return steps;
}

// The steps' dates, checked against the steps: one each, in increasing order (by their place in the year
// when the series repeats yearly, since that is the order it steps through).
TemporalSeries seriesOf(const NodeSetup& setup) {
  const std::vector<double>& dates = setup.parameters.reals("dates");
  const SourceLocation& where = setup.parameters.where("dates");
  const std::size_t steps = setup.inputList("steps").size();
  if (dates.size() != steps)
    throw Error(where, std::to_string(dates.size()) + " dates for " + std::to_string(steps) + " steps",
                "give one date per step, in the order of `steps`");
  const bool yearly = setup.parameters.string("repeat") == "yearly";
  for (std::size_t i = 1; i < dates.size(); ++i) {
    const double before = yearly ? yearFraction(dates[i - 1]) : dates[i - 1], now = yearly ? yearFraction(dates[i]) : dates[i];
    if (now <= before)
      throw Error(where, "the dates are not in increasing order" + std::string(yearly ? " within the year" : "") + ": " +
                             formatIsoDate(dates[i]) + " follows " + formatIsoDate(dates[i - 1]),
                  "list the steps and their dates from the earliest to the latest" +
                      std::string(yearly ? " day of the year" : ""));
  }
  return TemporalSeries(dates, yearly);
}

DayNumber sceneDate(const NodeSetup& setup) {
  if (!setup.date)
    throw Error(setup.where, "a temporal blend shows the scene's date, and the pipeline gives none",
                "add `date: 2004-06-15` (ISO 8601, UTC) at the top of the pipeline, or --set date=2004-06-15");
  return *setup.date;
}

class TemporalBlend : public Node {
 public:
  explicit TemporalBlend(const NodeSetup& setup)
      : steps_(stepLayers(setup)), series_(seriesOf(setup)), date_(sceneDate(setup)), layer_(setup.id, steps_) {
    layer_.show(series_.at(date_));
  }

  // The frame's date (the last one given, where a host cleared it): which two steps show, how far between
  // them, and which steps' pages are wanted.
  void prepare(const FrameState& frame) override {
    if (frame.date) date_ = *frame.date;
    const Bracket bracket = series_.at(date_);
    layer_.show(bracket);
    const std::vector<PageDemand> demands = series_.demands(bracket);
    for (std::size_t i = 0; i < steps_.size(); ++i) steps_[i]->setPageDemand(demands[i]);
  }

  Layer* layer() override { return &layer_; }

 private:
  std::vector<const Layer*> steps_;
  TemporalSeries series_;
  DayNumber date_;
  TemporalBlendLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.type = "composite.temporal_blend";
  type.category = NodeCategory::Compositor;
  type.summary = "A time series as one layer at the scene's date: the two bracketing steps blended linearly in time";
  type.inputs = {{.name = "steps", .type = PortType::Layer, .list = true,
                  .doc = "the series' layers, of one kind, from the earliest to the latest (one per date)"}};
  type.output = PortType::Layer;
  type.parameters = {
      {.name = "dates", .type = ParameterType::DateList,
       .doc = "each step's date, ISO 8601 in UTC (2004-01-15), in the order of `steps`: when it shows alone"},
      {.name = "repeat", .type = ParameterType::Choice, .defaultValue = std::string("none"),
       .doc = "none: before the first date and after the last, that step shows; yearly: the series is a climatology "
              "that repeats every year (months of any year), and the last step blends into the first",
       .choices = {"none", "yearly"}},
  };
  type.create = [](const NodeSetup& setup) { return std::make_unique<TemporalBlend>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-temporal-blend", "0.1.0", strata::composite::registerTypes)
