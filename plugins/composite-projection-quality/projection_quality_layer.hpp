#pragma once
#include <string>
#include <vector>

#include <strata/layer.hpp>

namespace strata::composite {

// The layers blended by how well each is sampled where it lands (seed 000 section 4.1; digest 000 section 5.1,
// method 2): per sample, each input's value counts with the isotropy of its texels there, times their
// resolution if asked, times its coverage; the sums normalise at the end (value x weight in rgb, weight in
// alpha: weights need not sum to one). Inputs without texels (procedural layers) count with weight 1.
class ProjectionQualityLayer : public Layer {
 public:
  ProjectionQualityLayer(const std::string& nodeId, std::vector<const Layer*> inputs);

  // n of the isotropy weight (alpha = 0 at texels n times longer than wide); whether resolution counts.
  void setWeighting(double quality, bool resolution);

  LayerKind kind() const override { return inputs_.front()->kind(); }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  std::optional<ValueRange> valueRange() const override;

 private:
  std::string accumulation() const;

  std::string prefix_;
  std::vector<const Layer*> inputs_;
  double quality_ = 4.0;
  bool resolution_ = true;
};

}  // namespace strata::composite
