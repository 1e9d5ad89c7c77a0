#pragma once
#include <string>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/layer_capabilities.hpp>

#include "planet_lattice.hpp"
#include "planet_model.hpp"

namespace strata::procedural {

// The procedural planet as a layer, computed per sample on the GPU (plugins/source-procedural/planet.glsl) at the
// sample's unit normal: no texture, so it is sharp at any distance, and the sample's footprint decides how
// many octaves it sums, so it never aliases. Heights (kind height) come multiplied by `scale`; colours
// (kind color) are those of the true heights, with their contour lines.
class ProceduralLayer : public Layer, public RegionalValueLayer {
 public:
  ProceduralLayer(const std::string& nodeId, LayerKind kind, const PlanetParameters& planet, double radius,
                  double scale);

  LayerKind kind() const override { return kind_; }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  // Heights: within +-amplitude x scale, which the noise never reaches (planet_model.hpp).
  std::optional<ValueRange> valueRange() const override;
  // Heights: bounded from the noise at the cap's centre and its slope (planet_bounds.hpp).
  std::optional<ValueRange> valuesWithin(const SphericalCap& cap) const override;
  // Samples the planet relative to the frame's reference from now on (planet_lattice.hpp); from prepare().
  void setReference(glm::dvec2 referenceLonlat);

 private:
  void bindLattice(ShaderProgram& program) const;

  std::string prefix_;  // GLSL identifier prefix unique to the node
  LayerKind kind_;
  PlanetParameters planet_;
  double radius_;
  double scale_;
  PlanetLattice lattice_;  // octaves 0 until setReference()
};

}  // namespace strata::procedural
