#pragma once
#include <string>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>

namespace strata::composite {

// Chroma from a low-resolution colour layer, luminance from a high-resolution one ([Kooima 2008, §1.1],
// HiRISE luminance with Viking chroma; [Kooima 2008, §3.4.3], colour-space transformations):
// per sample, the colour layer's colour goes into an opponent space (CIE L*a*b* or BT.709 Y'CbCr), its
// lightness channel moves `strength` of the way to the fused luminance's, its chroma stays, and it comes back
// to scene-linear light. The fused luminance is the luminance layer's own, or, matched, the colour layer's
// times the luminance layer's detail: its ratio to its own low-pass at the colour layer's resolution (itself
// sampled over a footprint widened to one colour texel: its coarser, box-filtered levels). Where the colour
// layer has no data the luminance shows as grey (with `strength` of its coverage), where the luminance has
// none the colour alone. Space, strength and matching are uniforms: changing them rebuilds no program.
class ChromaFusionLayer : public Layer, public ProjectedLayer {
 public:
  enum class Space { Lab, YCbCr };       // the order opponent_spaces.glsl numbers them
  enum class Matching { None, Detail };  // the order chroma_fusion.glsl's fusedLuminance numbers them

  struct Fusion {
    Space space = Space::Lab;
    double strength = 1.0;  // 0: the colour layer alone; 1: its lightness entirely the fused luminance's
    Matching matching = Matching::Detail;
  };

  // `luminance`: a luminance layer (its value) or a colour layer (its relative luminance). `colour`: a colour
  // layer; with Matching::Detail one of texels (texelStepsFunction), whose resolution the low-pass takes.
  ChromaFusionLayer(const std::string& nodeId, const Layer& luminance, const Layer& colour, Fusion fusion);

  LayerKind kind() const override { return LayerKind::Color; }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  // A new fusion for the next frame: its values are uniforms.
  void setFusion(Fusion fusion) { fusion_ = fusion; }
  // The colour layer's: the result has data where it has, the luminance only refining it.
  ProjectionAspect aspect() const override { return aspectOf(colour_); }
  void setPageDemand(PageDemand demand) const override;
  std::uint64_t revision() const override { return summedRevision({&luminance_, &colour_}); }

 private:
  std::string panLuminance() const;
  std::string panLowpass() const;
  std::string fused() const;

  std::string prefix_;
  const Layer& luminance_;
  const Layer& colour_;
  Fusion fusion_;
};

}  // namespace strata::composite
