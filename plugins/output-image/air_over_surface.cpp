#include "air_over_surface.hpp"

#include <strata/gl/shader_program.hpp>
#include <strata/sun.hpp>

namespace strata::image {
namespace {

// A GL texture holding `table`, read bilinearly between its points and clamped at its edges as
// AtmosphereTable::at reads it.
Texture uploaded(const AtmosphereTable& table) {
  Texture texture(GL_RGB32F, table.width, table.height);
  glTextureSubImage2D(texture.id(), 0, 0, 0, table.width, table.height, GL_RGB, GL_FLOAT, table.values.data());
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

}  // namespace

AirOverSurface::AirOverSurface(const NodeSetup& setup) {
  if (!setup.atmosphere) return;
  if (!setup.sun)
    throw Error(setup.atmosphere->where, "the atmosphere is lit by the sun, and the scene places none",
                "give the scene a date (the Earth's sun follows it) or a fixed sun: {lon, lat}");
  model_.emplace(*setup.atmosphere, setup.body->radius);
  tables_ = makeAtmosphereTables(*model_);
}

void AirOverSurface::createResources() {
  if (!model_) return;
  transmittance_ = uploaded(tables_.transmittance);
  multipleScattering_ = uploaded(tables_.multipleScattering);
}

void AirOverSurface::bind(ShaderProgram& program, TextureUnits& units, const FrameState& frame) const {
  if (!model_ || !frame.sun) return;
  const View& view = frame.view;
  program.set("airSun", glm::vec3(sunDirection(*frame.sun)));
  program.set("eyePosition", glm::vec3(view.eye));
  program.set("eyeToPlanet", glm::mat3(glm::transpose(view.planetToEye)));
  program.set("frameTangents", glm::vec2(view.halfFrameTangents()));
  program.set("nearPlane", float(view.near));
  const Atmosphere& air = model_->air();
  units.bind(program, "airTransmittance", transmittance_.id());
  units.bind(program, "airMultipleScattering", multipleScattering_.id());
  program.set("airRadii", glm::vec2(model_->bottom(), model_->top()));
  program.set("airRayleigh", glm::vec3(air.rayleighScattering));
  program.set("airMie", glm::vec3(air.mieScattering, air.mieExtinction, air.mieAsymmetry));
  program.set("airScaleHeights", glm::vec2(air.rayleighScaleHeight, air.mieScaleHeight));
}

}  // namespace strata::image
