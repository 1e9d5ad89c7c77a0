#pragma once
#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The figure a projection is defined on: a sphere (inverseFlattening 0) or an oblate ellipsoid of
// revolution, as the raster's CRS gives it (Earth's WGS84, the Mars and Moon spheres of the IAU).
struct Ellipsoid {
  double semiMajorAxis = 6378137.0;  // m
  double inverseFlattening = 0.0;    // 1/f; 0 for a sphere

  double flattening() const { return inverseFlattening == 0.0 ? 0.0 : 1.0 / inverseFlattening; }
  double eccentricitySquared() const { return flattening() * (2.0 - flattening()); }
};

// The "+key=value" terms of a PROJ string ("+proj=stere +lat_0=-90 +lat_ts=-71"), as a projection's
// factory receives them. Flags without a value ("+south", "+no_defs") map to an empty string.
class ProjParameters {
 public:
  // Throws strata::Error when `text` is not a sequence of +key[=value] terms.
  static ProjParameters parse(const std::string& text);

  std::string name() const;  // the +proj value
  bool has(const std::string& key) const { return terms_.contains(key); }
  // The value of `key` read as a number (degrees for angles, as in PROJ), or `fallback` when absent.
  // Throws strata::Error when present but not a number.
  double real(const std::string& key, double fallback) const;
  const std::map<std::string, std::string>& terms() const { return terms_; }

 private:
  std::map<std::string, std::string> terms_;
};

// Where a projection samples the body best, in cartography's terms of aspect: a cylindrical map in its normal
// (equatorial) aspect is true along the whole equator and stretches its texels towards the poles; an azimuthal
// map in a polar aspect is true at its pole and stretches them towards the equator. Compositors that weigh
// layers by latitude (composite.projection_quality's latitude method) read it.
enum class ProjectionAspect {
  Other,       // neither, or not said: oblique and transverse aspects (an azimuthal map centred on a point of
               // the equator samples a point well, not the equator), HEALPix, projections that do not tell
  Equatorial,  // cylindrical, normal aspect (longitude/latitude, eqc)
  NorthPolar,  // azimuthal, centred on the north pole (polar stereographic, orthographic at lat_0 = 90, ...)
  SouthPolar,  // azimuthal, centred on the south pole
};

// A map projection (docs/architecture.md, "Projections"): geodetic longitude and latitude in radians to map
// coordinates (x, y) in the units of the raster's geotransform (metres for projected CRSs, degrees for
// geographic ones), and back, in double precision. Its GLSL side does the forward mapping per vertex and
// per pixel with the same formulas in single precision.
class Projection {
 public:
  virtual ~Projection() = default;

  // The type name pipelines use ("equirectangular", "polar-stereographic", "healpix", ...).
  virtual std::string type() const = 0;
  // A PROJ string for the same mapping; tests check forward/inverse against PROJ through it.
  virtual std::string projString() const = 0;

  // Map coordinates of `lonlat`; empty where the projection is undefined (the far side of an
  // orthographic view). Longitudes may lie outside [-pi, pi]; periodic projections wrap them into
  // [centre - pi, centre + pi) (see setLongitudeCentre).
  virtual std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const = 0;
  // Longitude and latitude of map coordinates; empty outside the projection's domain.
  virtual std::optional<glm::dvec2> inverse(glm::dvec2 xy) const = 0;

  // The map-x period of projections that wrap around the body (360 degrees, or 2 pi a cos(lat_ts) m),
  // empty for the others. A raster that spans one period is filtered across its east/west seam.
  virtual std::optional<double> periodX() const { return std::nullopt; }
  // Periodic projections: the longitude (radians) around which forward() wraps, so that a raster whose
  // x range is, say, [0, 360) degrees sees longitudes in that range. Others ignore it.
  virtual void setLongitudeCentre(double) {}
  // The longitude (rad) around which forward() wraps; 0 for projections that do not wrap.
  virtual double longitudeCentre() const { return 0.0; }
  // Which region it samples best, from its parameters (e.g. PROJ's +lat_0 of an azimuthal map).
  virtual ProjectionAspect aspect() const { return ProjectionAspect::Other; }
  // Whether map x is an affine function of longitude (taken within half a turn of longitudeCentre()) and
  // map y one of latitude, as in a plate carree or eqc. Layers then address texels from each point's offset to
  // the frame's reference alone, exact at any distance from it, which costs a shader far less than the
  // projection's own GLSL and the polynomial about the reference (ProjectedRasterLayer::setReference).
  virtual bool affineInLonLat() const { return false; }

  // The GLSL side. glslInclude() names a file of the shader library that defines
  //   vec3 <glslFunction()>(vec2 lonlat, vec4 a, vec4 b)
  // returning (x, y) / glslMapScale() in .xy and 1.0 in .z where the projection is defined (0.0 where
  // not); a and b are glslParameters(), passed as uniforms so one program serves every instance.
  virtual std::string glslInclude() const = 0;
  virtual std::string glslFunction() const = 0;
  virtual std::array<glm::dvec4, 2> glslParameters() const = 0;
  // Map units per GLSL unit (the semi-major axis for metric projections), keeping GLSL values near 1.
  virtual double glslMapScale() const = 0;
};

// A kind of projection, as built-in code or a plugin registers it.
struct ProjectionDeclaration {
  std::string type;                    // the pipeline name, e.g. "polar-stereographic"
  std::string summary;                 // one line for `strata plugins`
  std::vector<std::string> projNames;  // the +proj= values it recognises, e.g. {"stere", "ups"}
  // Makes the projection for a CRS given as PROJ terms on `ellipsoid`. Returns nullptr when the terms are
  // a variant this type does not handle (an oblique stereographic), so that the caller can say so.
  // Throws strata::Error for values out of range.
  std::function<std::unique_ptr<Projection>(const ProjParameters&, const Ellipsoid&)> create;
  // GLSL files (name -> source) that its projections' glslInclude() names; the engine adds them to its
  // shader library. Empty for the built-in projections, whose GLSL ships in shaders/.
  std::map<std::string, std::string> shaderSources = {};
};

}  // namespace strata
STRATA_EXPORTS_END
