#include "procedural_layer.hpp"

#include <algorithm>
#include <cmath>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/spherical_cap.hpp>

#include "planet_bounds.hpp"

namespace strata::procedural {

ProceduralLayer::ProceduralLayer(const std::string& nodeId, LayerKind kind, const PlanetParameters& planet,
                                 double radius, double scale)
    : prefix_("procedural_" + glslIdentifier(nodeId)), kind_(kind), planet_(planet), radius_(radius), scale_(scale) {}

std::string ProceduralLayer::glsl() const {
  const std::string& p = prefix_;
  const std::string value = kind_ == LayerKind::Height ? "vec4(h * " + p + "_scale, 0.0, 0.0, 1.0)"
                                                       : "vec4(planetColour(h, " + p + "_planet), 1.0)";
  return "#include \"source-procedural/planet.glsl\"\n"
         "uniform ProceduralPlanet " +
         p +
         "_planet;\n"
         "uniform PlanetLattice " +
         p +
         "_lattice;\n"
         "uniform float " +
         p +
         "_scale;\n"
         "vec4 " +
         p +
         "(SurfacePoint p) {\n"
         "  float h = planetHeightAt(p, planetFootprint(p, " +
         p + "_planet.radius), " + p + "_planet, " + p +
         "_lattice);\n"
         "  return " +
         value +
         ";\n"
         "}\n";
}

std::optional<ValueRange> ProceduralLayer::valueRange() const {
  if (kind_ != LayerKind::Height) return std::nullopt;
  const double reach = planet_.amplitude * std::abs(scale_);
  return ValueRange{-reach, reach};
}

std::optional<ValueRange> ProceduralLayer::valuesWithin(const SphericalCap& cap) const {
  if (kind_ != LayerKind::Height) return std::nullopt;
  const HeightBounds bounds = heightsWithin(PlanetModel(planet_, radius_), cap.centre, cap.angle);
  const double a = bounds.least * scale_, b = bounds.greatest * scale_;
  return ValueRange{std::min(a, b), std::max(a, b)};
}

void ProceduralLayer::setReference(glm::dvec2 referenceLonlat) {
  lattice_ = planetLattice(planet_, radius_, referenceLonlat);
}

void ProceduralLayer::bindLattice(ShaderProgram& program) const {
  const std::string lattice = prefix_ + "_lattice.";
  for (int k = 0; k < lattice_.octaves; ++k) {
    const std::string index = "[" + std::to_string(k) + "]";
    program.set(lattice + "anchor" + index, lattice_.anchor[std::size_t(k)]);
    program.set(lattice + "local" + index, glm::vec3(lattice_.local[std::size_t(k)]));
  }
  program.set(lattice + "octaves", lattice_.octaves);
  program.set(lattice + "frame", glm::mat3(lattice_.frame));
  program.set(lattice + "latitude", glm::vec2(lattice_.latitude));
}

void ProceduralLayer::bind(ShaderProgram& program, TextureUnits&) const {
  const std::string planet = prefix_ + "_planet.";
  program.set(planet + "seed", int(planet_.seed));
  program.set(planet + "amplitude", float(planet_.amplitude));
  program.set(planet + "wavelength", float(planet_.wavelength));
  program.set(planet + "octaves", planet_.octaves);
  program.set(planet + "contourInterval", float(planet_.contourInterval));
  program.set(planet + "radius", float(radius_));
  program.set(prefix_ + "_scale", float(scale_));
  bindLattice(program);
}

}  // namespace strata::procedural
