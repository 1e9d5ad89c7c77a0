#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include <strata/plugin/layer.hpp>

namespace strata::composite {

// The layers blended by how well each is sampled where it lands [Kooima 2008, §4.1]:
// per sample, each input's value counts with its weight times its coverage, and the sums normalise at the end
// (value x weight in rgb, weight in alpha: weights need not sum to one). The weight is, by method,
//   isotropy (method 2): the isotropy of its texels there, times their resolution if asked; inputs without
//     texels (procedural layers) count with weight 1;
//   latitude (method 1): a smoothstep of latitude across a band, by the region its projection samples best
//     (Layer::aspect(), which every input must tell: see the node's check).
class ProjectionQualityLayer : public Layer {
 public:
  enum class Method { Isotropy, Latitude };
  struct Weighting {
    Method method = Method::Isotropy;
    double quality = 4.0;    // isotropy: n of the weight (alpha = 0 at texels n times longer than wide)
    bool resolution = true;  // isotropy: whether resolution counts too
    glm::dvec2 band{0.0};    // latitude: the inner and outer |latitude| of the band, rad
  };

  ProjectionQualityLayer(const std::string& nodeId, std::vector<const Layer*> inputs);

  void setWeighting(const Weighting& weighting) { weighting_ = weighting; }

  LayerKind kind() const override { return inputs_.front()->kind(); }
  std::uint64_t revision() const override { return summedRevision(inputs_); }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  std::optional<ValueRange> valueRange() const override;

 private:
  std::string accumulation() const;
  std::string isotropyWeight(const Layer& input) const;
  std::string latitudeWeight(const Layer& input) const;

  std::string prefix_;
  std::vector<const Layer*> inputs_;
  Weighting weighting_;
};

}  // namespace strata::composite
