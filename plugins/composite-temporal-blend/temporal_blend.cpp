// composite.temporal_blend: a time series (Blue Marble Next Generation's twelve monthly mosaics; any rasters
// with dates) as one layer at the scene's date, the two bracketing steps blended linearly in time, in geometry
// and imagery alike ([Kooima 2008, §1.1, ch. 6], time-varying data).
#include <memory>
#include <string>
#include <vector>

#include <strata/plugin/node.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/plugin.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "dated_files.hpp"
#include "plugin_shaders.hpp"
#include "temporal_blend_layer.hpp"
#include "temporal_series.hpp"

namespace strata::composite {
namespace {

// The node's settings as a pipeline writes them.
struct TemporalBlendSettings {
  std::vector<double> dates;   // none: the steps come from `files`
  std::string files;           // none: the steps come from `steps` and `dates`
  std::string kind = "color";  // source.gdal's own default
  bool yearly = false;         // repeat: none
};

const ParameterBindings<TemporalBlendSettings>& temporalBlendParameters() {
  using S = TemporalBlendSettings;
  static const auto bindings =
      ParameterBindings<S>()
          .add(&S::dates,
               {.name = "dates",
                .type = ParameterType::DateList,
                .doc = "each step's date, ISO 8601 in UTC (2004-01-15), in the order of `steps`: when it shows alone"})
          .add(&S::files, {.name = "files",
                           .doc = "instead of steps and dates: a file-name pattern whose %Y %m %d %j give each file's "
                                  "date and * any text (bmng/world.%Y%m.*.jpg), each file read as source.gdal reads "
                                  "it; empty: use `steps`"})
          .add(&S::kind, {.name = "kind",
                          .doc = "what the files `files` matches hold, as source.gdal's `kind`",
                          .choices = {"color", "height", "scalar", "luminance", "mask"}})
          .choice(&S::yearly,
                  {.name = "repeat",
                   .doc = "none: before the first date and after the last, that step shows; yearly: the series is a "
                          "climatology that repeats every year (months of any year), and the last step blends into "
                          "the first"},
                  {{"none", false}, {"yearly", true}});
  return bindings;
}

// A series' steps and their dates, from the pipeline's `steps` and `dates`, or from the files a `files`
// pattern matches, each read by a source.gdal node the temporal blend makes and runs itself.
struct Steps {
  std::vector<std::unique_ptr<Node>> own;  // from `files`: the nodes reading them
  std::vector<Node*> nodes;
  std::vector<DayNumber> dates;
};

// The parameters source.gdal would take for `file` with every other parameter at its default.
ParameterSet fileStepParameters(const NodeTypeDeclaration& type, const std::filesystem::path& file,
                                const std::string& kind, const SourceLocation& where) {
  ParameterSet parameters;
  for (const ParameterDeclaration& parameter : type.parameters)
    if (parameter.defaultValue) parameters.set(parameter.name, *parameter.defaultValue, where);
  parameters.set("path", file.string(), where);
  parameters.set("kind", kind, where);
  return parameters;
}

Steps stepsFromFiles(const NodeSetup& setup, const TemporalBlendSettings& settings) {
  const SourceLocation& where = temporalBlendParameters().where(setup.parameters, &TemporalBlendSettings::files);
  if (!setup.inputList("steps").empty() || !settings.dates.empty())
    throw Error(where, "the steps are given twice: by `files` and by `steps` and `dates`",
                "keep `files` (the dates come from the file names) or `steps` with `dates`, not both");
  const NodeTypeDeclaration* reader = setup.plugins->find("source.gdal");
  if (!reader)
    throw Error(where, "`files` reads its steps with source.gdal, which is not loaded",
                "install the source-gdal plugin");
  Steps steps;
  for (const DatedFile& file : datedFiles(settings.files, setup.pipelineDirectory, where)) {
    NodeSetup step{setup.id + "/" + file.path.filename().string(),
                   where,
                   fileStepParameters(*reader, file.path, settings.kind, where),
                   {},
                   setup.body,
                   setup.pipelineDirectory,
                   setup.plugins,
                   setup.date,
                   setup.colour};
    steps.own.push_back(reader->create(step));
    steps.nodes.push_back(steps.own.back().get());
    steps.dates.push_back(file.date);
  }
  return steps;
}

// One date per listed step, in increasing order (by their place in the year when the series repeats
// yearly, since that is the order it steps through).
Steps stepsFromList(const NodeSetup& setup, const TemporalBlendSettings& settings) {
  const std::vector<double>& dates = settings.dates;
  const SourceLocation& where = temporalBlendParameters().where(setup.parameters, &TemporalBlendSettings::dates);
  const std::vector<Node*>& nodes = setup.inputList("steps");
  if (nodes.empty())
    throw Error(setup.where, "the series has no steps",
                "give `steps: [...]` with `dates: [...]`, or `files:` with a file-name pattern such as world.%Y%m.tif");
  if (dates.size() != nodes.size())
    throw Error(where, std::to_string(dates.size()) + " dates for " + std::to_string(nodes.size()) + " steps",
                "give one date per step, in the order of `steps`");
  const bool yearly = settings.yearly;
  for (std::size_t i = 1; i < dates.size(); ++i) {
    const double before = yearly ? yearFraction(dates[i - 1]) : dates[i - 1],
                 now = yearly ? yearFraction(dates[i]) : dates[i];
    if (now <= before)
      throw Error(where,
                  "the dates are not in increasing order" + std::string(yearly ? " within the year" : "") + ": " +
                      formatIsoDate(dates[i]) + " follows " + formatIsoDate(dates[i - 1]),
                  "list the steps and their dates from the earliest to the latest" +
                      std::string(yearly ? " day of the year" : ""));
  }
  return {{}, nodes, dates};
}

Steps stepsOf(const NodeSetup& setup, const TemporalBlendSettings& settings) {
  return settings.files.empty() ? stepsFromList(setup, settings) : stepsFromFiles(setup, settings);
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
      : TemporalBlend(setup, temporalBlendParameters().read(setup.parameters)) {}

  // The steps the node reads itself (`files`) go through the scheduler's calls with it.
  void open() override {
    for (const auto& step : steps_.own) step->open();
  }
  void createResources(GpuContext& gpu) override {
    for (const auto& step : steps_.own) step->createResources(gpu);
  }

  // The frame's date (the last one given, where a host cleared it): which two steps show, how far between
  // them, and which steps' pages are wanted.
  void prepare(const FrameState& frame) override {
    for (const auto& step : steps_.own) step->prepare(frame);
    if (frame.date) date_ = *frame.date;
    const Bracket bracket = series_.at(date_);
    layer_.show(bracket);
    const std::vector<PageDemand> demands = series_.demands(bracket);
    for (std::size_t i = 0; i < layers_.size(); ++i) layers_[i]->setPageDemand(demands[i]);
  }
  void render(const FrameState& frame) override {
    for (const auto& step : steps_.own) step->render(frame);
  }

  Layer* layer() override { return &layer_; }

 private:
  TemporalBlend(const NodeSetup& setup, const TemporalBlendSettings& settings)
      : steps_(stepsOf(setup, settings)),
        layers_(layersOfOneKind(steps_.nodes, "steps", setup.where)),
        series_(steps_.dates, settings.yearly),
        date_(sceneDate(setup)),
        layer_(setup.id, layers_) {
    layer_.show(series_.at(date_));
  }

  Steps steps_;
  std::vector<const Layer*> layers_;
  TemporalSeries series_;
  DayNumber date_;
  TemporalBlendLayer layer_;
};

NodeTypeDeclaration declaration() {
  NodeTypeDeclaration type;
  type.shaderSources = strata::plugin::shaderSources();  // this plugin's GLSL files
  type.type = "composite.temporal_blend";
  type.category = NodeCategory::Compositor;
  type.summary = "A time series as one layer at the scene's date: the two bracketing steps blended linearly in time";
  type.inputs = {
      {.name = "steps",
       .type = PortType::Layer,
       .list = true,
       .optional = true,
       .doc = "the series' layers, of one kind, from the earliest to the latest (one per date); or `files`"}};
  type.output = PortType::Layer;
  type.parameters = temporalBlendParameters().declarations();
  type.create = [](const NodeSetup& setup) { return std::make_unique<TemporalBlend>(setup); };
  return type;
}

void registerTypes(PluginRegistrar& registrar) { registrar.add(declaration()); }

}  // namespace
}  // namespace strata::composite

STRATA_PLUGIN("composite-temporal-blend", "0.1.0", strata::composite::registerTypes)
