#pragma once
#include <atomic>
#include <string>
#include <vector>

#include <strata/layer.hpp>

#include "temporal_series.hpp"

namespace strata::composite {

// A time series as one layer at the scene's date ([Kooima 2008, §1.1, ch. 6], time-varying data): the two
// steps that bracket the date, mixed linearly in time, each by its coverage, so that the layer changes
// continuously with the date and never pops from one step to the next. Every step's sampling is in the
// program once; two uniforms choose the bracketing pair, so stepping through time recompiles nothing. Steps may be
// any layers of one kind, compositors included.
class TemporalBlendLayer : public Layer {
 public:
  TemporalBlendLayer(const std::string& nodeId, std::vector<const Layer*> steps);

  // The bracket the next frames show (from prepare(), before the frame's bind()).
  void show(const Bracket& bracket);

  LayerKind kind() const override { return steps_.front()->kind(); }
  std::string samplingFunction() const override { return prefix_; }
  std::string texelStepsFunction() const override;
  std::string edgeDistanceFunction() const override;
  std::string faceSamplingFunction() const override;
  ProjectionAspect aspect() const override;
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  std::optional<ValueRange> valueRange() const override;

 private:
  // Whether every step offers the function `of` names (Layer's optional functions).
  bool everyStepHas(std::string (Layer::*of)() const) const;
  std::string stepDispatch(std::string (Layer::*of)() const, const std::string& name, const std::string& type,
                           const std::string& parameters, const std::string& arguments) const;

  std::string prefix_;
  std::vector<const Layer*> steps_;
  std::atomic<int> earlier_{0}, later_{0};
  std::atomic<float> fraction_{0.0f};
};

}  // namespace strata::composite
