#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include <strata/plugin/layer.hpp>

namespace strata::composite {

// Shaded relief of a height layer [Kooima 2008, §1.1]: the composed height's
// gradient over a pixel's footprint along the ground gives the surface normal in the local east/north/up
// frame, and the Lambertian cosine of its angle to a light at an azimuth and altitude (or to four, in the
// multidirectional mode), or to the sun as it stands over each point, is the shade, grey alone or multiplied
// over a surface layer; or it shows the slope
// or the aspect instead; a tint (a colour ramp by elevation or by slope) colours it. The light and the exaggeration are
// uniforms: changing them rebuilds no program.
class ReliefLayer : public Layer {
 public:
  enum class Output { Shade, Slope, Aspect };  // the order the shader's _output uniform numbers them

  enum class Tint { None, Elevation, Slope };   // the order the shader's _tint uniform numbers them
  static constexpr std::size_t kRampStops = 8;  // relief.glsl's RELIEF_RAMP_STOPS

  // A colour ramp: stops of (value, red, green, blue), values rising, colours sRGB-encoded in [0, 1].
  struct Ramp {
    Tint by = Tint::None;
    std::vector<double> stops;
  };

  struct Lighting {
    double azimuth = 315.0;  // deg clockwise from north
    double altitude = 45.0;  // deg above the horizon
    double exaggeration = 1.0;
    bool multiply = true;           // over `surface` where one is given; else the grey shade alone
    bool multidirectional = false;  // Mark's four oblique-weighted lights, at `altitude`, not one at `azimuth`
    Output output = Output::Shade;
    Ramp tint;
    bool normalised = false;  // the shade over flat ground's, sin(altitude): flat ground keeps the surface's colour
    bool sun = false;         // lit by the sun (setSun) as it stands over each point, not at azimuth and altitude
  };

  // `surface`, or none: the colour layer to shade. `radius`: the body's, to turn angles into metres.
  ReliefLayer(const std::string& nodeId, const Layer& height, const Layer* surface, Lighting lighting, double radius);

  LayerKind kind() const override { return LayerKind::Color; }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  std::uint64_t revision() const override { return height_.revision() + (surface_ ? surface_->revision() : 0); }
  // The shade is light: lit again by the output it would show twice. Normalised, it is relief over flat ground's
  // own colour, which the output's light lights; the slope and the aspect are data.
  bool shaded() const override { return lighting_.output == Output::Shade && !lighting_.normalised; }
  // New lighting for the next frame: its values are uniforms.
  void relight(Lighting lighting) { lighting_ = std::move(lighting); }
  // The planet-fixed unit vector toward the sun, for Lighting::sun, from the next frame on.
  void setSun(const glm::dvec3& towardSun) { sun_ = glm::vec3(towardSun); }

  // The unit vector towards the light in the local east/north/up frame.
  static glm::vec3 lightDirection(double azimuthDegrees, double altitudeDegrees);

 private:
  std::string value() const;
  std::string tint() const;
  void bindRamp(ShaderProgram& program) const;
  std::string shadingGlsl() const;

  std::string prefix_;
  const Layer& height_;
  const Layer* surface_;
  Lighting lighting_;
  double radius_;
  glm::vec3 sun_{0.0f, 0.0f, 1.0f};
};

}  // namespace strata::composite
