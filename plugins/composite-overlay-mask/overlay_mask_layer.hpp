#pragma once
#include <string>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>

namespace strata::composite {

// A local layer laid over a base layer ([Kooima 2008, §4.2], laid on top rather than averaged with the base as
// its "accumulated normally" would; docs/references.md, Errata): where the overlay has data (its extent,
// nodata and alpha: its coverage, times a mask layer's value where one is given) it hides the base, with a
// hard edge or one feathered over a width in the overlay's texels or in metres, from that coverage averaged
// over half the width; elsewhere the base shows. Where the overlay has no data its sampling returns at once,
// so the work stays within its bounds.
class OverlayMaskLayer : public Layer, public ProjectedLayer {
 public:
  // A feather of 0 is a hard edge. `radius`: the body's, to turn metres into angles.
  struct Edge {
    double feather = 0.0;
    bool metres = false;  // the feather's unit: metres, else the overlay's texels
    double radius = 1.0;
  };

  // `mask`, or none: a layer whose value (.r, clamped to [0, 1]) times its coverage limits the overlay's.
  OverlayMaskLayer(const std::string& nodeId, const Layer& base, const Layer& overlay, const Layer* mask, Edge edge);

  LayerKind kind() const override { return base_.kind(); }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  // The base's: what the composed layer is, but for the overlay's local patch.
  ProjectionAspect aspect() const override { return aspectOf(base_); }
  void setPageDemand(PageDemand demand) const override;
  std::uint64_t revision() const override {
    return summedRevision({&base_, &overlay_}) + (mask_ ? mask_->revision() : 0);
  }
  std::optional<ValueRange> valueRange() const override;

 private:
  std::string coverage() const;
  std::string edgeWeight() const;

  std::string prefix_;
  const Layer& base_;
  const Layer& overlay_;
  const Layer* mask_;
  Edge edge_;
};

}  // namespace strata::composite
