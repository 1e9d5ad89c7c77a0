#pragma once
#include <optional>

#include <strata/atmosphere.hpp>
#include <strata/atmosphere_tables.hpp>
#include <strata/gl/texture.hpp>
#include <strata/plugin/node.hpp>

namespace strata {
class ShaderProgram;
class TextureUnits;
}  // namespace strata

namespace strata::image {

// The body's air as output.image draws it (docs/atmosphere.md): the sky where no surface shows, the haze
// between the eye and distant ground (aerial perspective), and the sun's light reddened on its way down
// (shaders/strata/atmosphere.glsl). Its tables are computed once, on the CPU in double, when the node is made, and
// uploaded when the GL resources are.
class AirOverSurface {
 public:
  // The body's `atmosphere:` over its radius, and its tables. Throws strata::Error at it where the scene places no
  // sun to light it.
  explicit AirOverSurface(const NodeSetup& setup);

  explicit operator bool() const { return model_.has_value(); }
  double thickness() const { return model_ ? model_->air().thickness : 0.0; }  // m; 0 where airless

  void createResources();
  // Binds the tables, the air's coefficients, the frame's sun, and what turns the frame's pixels into rays from
  // the eye (composite.frag's throughAir): the view's. Nothing where airless.
  void bind(ShaderProgram& program, TextureUnits& units, const FrameState& frame) const;

 private:
  std::optional<AtmosphereModel> model_;
  AtmosphereTables tables_;
  Texture transmittance_, multipleScattering_;
};

}  // namespace strata::image
