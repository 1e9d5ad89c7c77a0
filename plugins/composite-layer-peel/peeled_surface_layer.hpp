#pragma once
#include <string>
#include <utility>
#include <vector>

#include <strata/plugin/layer.hpp>

#include "peel_layer.hpp"

namespace strata::composite {

// The colours of what a composite.layer_peel shows ([Kooima 2008, §1.1, ch. 6], layered data peeling): where
// a layer's surface shows, that layer's surface colours (its imagery); where the cut runs through a layer's
// material (below its surface and above the next one's: the floor of a peel `depth` and the sloping walls
// of a cutaway's `edge`), that layer's cut-face colour, so the walls show the stack's strata in section.
class PeeledSurfaceLayer : public Layer {
 public:
  // `surfaces`: one colour layer per layer of `peel`'s stack, top first (one may serve several); `faces`: its cut
  // faces' colours, sRGB-encoded in [0, 1], three numbers per layer, top first.
  PeeledSurfaceLayer(const std::string& nodeId, const PeelLayer& peel, std::vector<const Layer*> surfaces,
                     std::vector<double> faces);

  LayerKind kind() const override { return LayerKind::Color; }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  std::uint64_t revision() const override { return peel_.revision() + summedRevision(surfaces_); }
  // New cut-face colours for the next frame: they are uniforms.
  void recolour(std::vector<double> faces) { faces_ = std::move(faces); }

 private:
  std::string exposed() const;
  std::string surfaceColour() const;

  std::string prefix_;
  const PeelLayer& peel_;
  std::vector<const Layer*> surfaces_;
  std::vector<const Layer*> distinct_;  // surfaces_ with each layer once: its GLSL is pasted once
  std::vector<double> faces_;
};

}  // namespace strata::composite
