#pragma once
#include <atomic>
#include <string>
#include <vector>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>

#include "temporal_series.hpp"

namespace strata::composite {

// A time series as one layer at the scene's date ([Kooima 2008, §1.1, ch. 6], time-varying data): the two
// steps that bracket the date, mixed linearly in time, each by its coverage, so that the layer changes
// continuously with the date and never pops from one step to the next. Every step's sampling is in the
// program once; two uniforms choose the bracketing pair, so stepping through time recompiles nothing. Steps may be
// any layers of one kind, compositors included.
// It offers its steps' capabilities where every step has them: texels, aspect, HEALPix faces (never their
// node bounds, which would need the series' every step).
class TemporalBlendLayer : public Layer, public TexelledLayer, public ProjectedLayer, public HealpixFaceLayer {
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
  std::optional<ValueRange> faceNodeValues(int, int, std::int64_t, std::int64_t) const override { return std::nullopt; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  std::optional<ValueRange> valueRange() const override;
  std::uint64_t revision() const override { return summedRevision(steps_) + reshown_; }

 private:
  // A GLSL function a layer names: Layer::samplingFunction, or a capability's (texelStepsFunctionOf...).
  using FunctionOf = std::string (*)(const Layer&);
  // Whether every step offers the function `of` names (a capability's).
  bool everyStepHas(FunctionOf of) const;
  std::string stepDispatch(FunctionOf of, const std::string& name, const std::string& type,
                           const std::string& parameters, const std::string& arguments) const;
  std::string bracketingSteps(const std::string& dispatch, const std::string& parameters, const std::string& arguments,
                              const std::string& suffix = "") const;

  std::string prefix_;
  std::vector<const Layer*> steps_;
  std::atomic<int> earlier_{0}, later_{0};
  std::atomic<float> fraction_{0.0f};
  std::atomic<std::uint64_t> reshown_{0};  // times show() changed the bracket
};

}  // namespace strata::composite
