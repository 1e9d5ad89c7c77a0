#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/healpix_pyramid.hpp>
#include <strata/plugin/projected_raster_layer.hpp>

#include "layers/block_caps.hpp"
#include "layers/local_texture_frame.hpp"

namespace strata {
namespace {

bool isColour(LayerKind kind) {
  return kind == LayerKind::Color || kind == LayerKind::Chroma || kind == LayerKind::Normal;
}

// Whether a raster `width` texels wide spans one period of a periodic projection.
bool spansPeriod(const RasterGeoreference& georeference, int width) {
  const std::optional<double> period = georeference.projection->periodX();
  return period && std::abs(std::abs(georeference.geotransform[1]) * width - *period) <= 1e-9 * *period;
}

// Texture coordinates per GLSL map unit: u = x * s.x + s.y, v = y * s.z + s.w (see Projection::glslMapScale).
glm::vec4 mapToTextureOf(const RasterGeoreference& georeference, int width, int height) {
  const std::array<double, 6>& t = georeference.geotransform;
  const double scale = georeference.projection->glslMapScale();
  const double uSpan = t[1] * width, vSpan = t[5] * height;
  return glm::vec4(glm::dvec4(scale / uSpan, -t[0] / uSpan, scale / vSpan, -t[3] / vSpan));
}

// A hundredth of a level-0 texel: the relative path's error, far below what filtering blurs.
constexpr double kRelativeTolerance = 0.01;

glm::vec4 columns(const glm::dmat2& m) { return glm::vec4(glm::dvec4(m[0], m[1])); }

// A GLSL uniform declaration.
std::string uniform(const std::string& type, const std::string& name) { return "uniform " + type + " " + name + ";\n"; }

}  // namespace

ProjectedRasterLayer::ProjectedRasterLayer(std::string nodeId, LayerKind kind)
    : prefix_("layer_" + glslIdentifier(nodeId)), kind_(kind) {}

void ProjectedRasterLayer::setValueTransform(double scale, double offset) {
  scale_ = scale;
  offset_ = offset;
}

std::optional<ValueRange> ProjectedRasterLayer::valueRange() const {
  if (!rawRange_ || isColour(kind_)) return std::nullopt;
  return transformed(rawRange_->least, rawRange_->greatest);
}

std::optional<ValueRange> ProjectedRasterLayer::valuesWithin(const SphericalCap& cap) const {
  if (!blockCaps_ || isColour(kind_)) return std::nullopt;
  const BlockValues found = blockCaps_->within(cap);
  if (!found.counted()) return ValueRange{};
  ValueRange values = transformed(found.least, found.greatest);
  values.finest = BlockRelief{found.blockRange * std::abs(scale_), found.blockWidth, found.curvature * std::abs(scale_),
                              found.texel};
  if (found.gaps) {  // the sphere shows there: a cliff down to it, which no curvature bounds
    values.least = std::min(values.least, 0.0);
    values.greatest = std::max(values.greatest, 0.0);
    values.finest->curvature = std::numeric_limits<double>::infinity();
  }
  return values;
}

ValueRange ProjectedRasterLayer::transformed(double rawLeast, double rawGreatest) const {
  const double a = rawLeast * scale_ + offset_, b = rawGreatest * scale_ + offset_;
  return ValueRange{std::min(a, b), std::max(a, b)};  // a negative scale turns the range over
}

void ProjectedRasterLayer::place(RasterGeoreference georeference, int width, int height) {
  georeference_ = std::move(georeference);
  reference_.reset();  // the terms about it are the old raster's
  const std::array<glm::dvec4, 2> projection = georeference_.projection->glslParameters();
  projection_ = {glm::vec4(projection[0]), glm::vec4(projection[1])};
  mapToTexture_ = mapToTextureOf(georeference_, width, height);
  size_ = glm::ivec2(width, height);
  repeatX_ = spansPeriod(georeference_, width);
  affine_ = georeference_.projection->affineInLonLat();
  if (affine_) {
    localTerms_ = {columns(affineJacobian()), glm::vec4(0.0f), glm::vec4(0.0f)};
    setAffineReference(glm::dvec2(0.0));  // until told a reference: offsets from (0, 0), the lon/lat
  }
  if (blockRanges_) blockCaps_ = std::make_shared<const BlockCaps>(blockRanges_, georeference_, repeatX_);
}

std::optional<glm::dvec2> ProjectedRasterLayer::textureCoordinates(glm::dvec2 lonlat) const {
  const std::array<double, 6>& t = georeference_.geotransform;
  const std::optional<glm::dvec2> xy = georeference_.projection->forward(lonlat);
  if (!xy) return std::nullopt;
  return glm::dvec2((xy->x - t[0]) / (t[1] * size_.x), (xy->y - t[3]) / (t[5] * size_.y));
}

void ProjectedRasterLayer::setReference(glm::dvec2 referenceLonlat) {
  if (reference_ == referenceLonlat) return;
  reference_ = referenceLonlat;
  if (affine_) {
    setAffineReference(referenceLonlat);
    return;
  }
  const TextureMapping mapping = [this](glm::dvec2 lonlat) { return textureCoordinates(lonlat); };
  const LocalTextureFrame frame =
      localTextureFrame(mapping, referenceLonlat, kRelativeTolerance / glm::dvec2(size_), repeatX_);
  setReferenceTexel(frame.uv);
  localTerms_ = {columns(frame.jacobian), columns(frame.hessianU), columns(frame.hessianV)};
  reach_ = float(frame.reach);
  tangent_ = frame.coordinates == LocalCoordinates::Tangent;
  referenceLatitude_ = glm::vec2(std::sin(referenceLonlat.y), std::cos(referenceLonlat.y));
}

void ProjectedRasterLayer::setReferenceTexel(glm::dvec2 uv) {
  // A raster around the body: u at the reference taken into [0, 1), where float keeps its digits.
  if (repeatX_) uv.x -= std::floor(uv.x);
  referenceUv_ = glm::vec2(uv);
  const glm::dvec2 texel = uv * glm::dvec2(size_);
  referenceTexel_ = glm::ivec2(glm::floor(texel));
  referenceFraction_ = glm::vec2(texel - glm::floor(texel));
}

// An affine projection's derivatives are the same everywhere: taken a radian either side of its centre, half a
// turn from where it wraps, they are exact to rounding. Once, when the raster is placed.
glm::dmat2 ProjectedRasterLayer::affineJacobian() const {
  const double centre = georeference_.projection->longitudeCentre();
  const glm::dvec2 east = *textureCoordinates({centre + 1.0, 0.0}) - *textureCoordinates({centre - 1.0, 0.0});
  const glm::dvec2 north = *textureCoordinates({centre, 0.5}) - *textureCoordinates({centre, -0.5});
  return glm::dmat2(0.5 * east, north);
}

// The reference's longitude taken within half a turn of the map's centre, as forward() takes it; the centre's
// offset from there bounds the offsets the shader wraps.
void ProjectedRasterLayer::setAffineReference(glm::dvec2 referenceLonlat) {
  constexpr double pi = std::numbers::pi;
  const double centre = georeference_.projection->longitudeCentre();
  const double longitude = referenceLonlat.x - 2.0 * pi * std::floor((referenceLonlat.x - centre + pi) / (2.0 * pi));
  setReferenceTexel(*textureCoordinates({longitude, referenceLonlat.y}));
  centreFromReference_ = float(centre - longitude);
}

std::string ProjectedRasterLayer::samplingGlsl(const std::string& declarations, const std::string& filtered,
                                               bool sloped) const {
  const std::string& p = prefix_;
  const bool colour = isColour(kind_);
  const std::string value = colour
                                ? "vec4(t.rgb / t.a, t.a)"
                                : "vec4(t.r / t.g * " + p + "_scaleOffset.x + " + p + "_scaleOffset.y, 0.0, 0.0, t.g)";
  const std::string coverage = colour ? "t.a" : "t.g";
  return "#include \"strata/projected_raster.glsl\"\n" + uniform("vec2", p + "_scaleOffset") +
         uniform("bool", p + "_repeatX") + uniform("ivec2", p + "_size") + declarations +
         (affine_ ? affineGlsl() : absoluteGlsl() + relativeGlsl()) + texelGlsl() + "vec4 " + p +
         "_value(vec4 t) { return " + coverage + " > 0.0 ? " + value + " : vec4(0.0); }\n" + "vec4 " + p +
         "(SurfacePoint p) {\n" + filteredAt() + "  return " + p + "_value(" + filtered + ");\n}\n" +
         (sloped && oneChannel() ? slopedGlsl(filtered) : std::string());
}

// The sampling functions' common start: texture coordinates, whether they fall on the raster, and the footprint's
// steps.
std::string ProjectedRasterLayer::filteredAt() const {
  const std::string& p = prefix_;
  return "  vec3 at = " + p + "_at(p);\n  bool repeatX = " + p +
         "_repeatX;\n"
         "  if (!insideTexture(at, repeatX)) return vec4(0.0);\n"
         "  vec2 uv = at.xy, stepX = " +
         p + "_step(at, p, p.lonlatDx), stepY = " + p + "_step(at, p, p.lonlatDy);\n";
}

// slopedSamplingFunction(): the filtered texel's slopes (a value page's .b and .a) turned along the ground by the
// projection's steps over one footprint east and north (a footprint east is footprint / cos(latitude) of longitude).
std::string ProjectedRasterLayer::slopedGlsl(const std::string& filtered) const {
  const std::string& p = prefix_;
  return "vec4 " + p + "_sloped(SurfacePoint p) {\n" + filteredAt() + "  vec4 t = " + filtered +
         ";\n"
         "  float d = groundFootprint(p);\n"
         "  vec2 east = " +
         p + "_step(at, p, vec2(d / max(cos(p.lonlat.y), 1e-4), 0.0)) * vec2(" + p + "_size) / d;\n" +
         "  vec2 north = " + p + "_step(at, p, vec2(0.0, d)) * vec2(" + p + "_size) / d;\n" +
         "  return slopedValue(t, east, north, " + p + "_scaleOffset);\n}\n";
}

// Texture coordinates and footprint steps at absolute longitude and latitude, through the projection's GLSL.
std::string ProjectedRasterLayer::absoluteGlsl() const {
  const std::string& p = prefix_;
  const Projection& projection = *georeference_.projection;
  return "#include \"" + projection.glslInclude() + "\"\n" + uniform("vec4", p + "_projectionA") +
         uniform("vec4", p + "_projectionB") + uniform("vec4", p + "_mapToTexture") + "vec3 " + p +
         "_coordinates(vec2 lonlat) {\n"
         "  vec3 m = " +
         projection.glslFunction() + "(lonlat, " + p + "_projectionA, " + p +
         "_projectionB);\n"
         "  return vec3(m.xy * " +
         p + "_mapToTexture.xz + " + p +
         "_mapToTexture.yw, m.z);\n"
         "}\n"
         "vec2 " +
         p +
         "_absoluteStep(vec3 at, vec2 lonlat, vec2 step) {\n"
         "  return footprintStep(at, " +
         p +
         "_coordinates(steppedLonlat(lonlat, step)),\n"
         "                       " +
         p + "_coordinates(steppedLonlat(lonlat, -step)), " + p +
         "_repeatX);\n"
         "}\n";
}

// What the relative paths share: the reference's texture coordinates and level-0 texel (whole, and the fraction
// beyond it), and the jacobian of texture coordinates by offsets there.
std::string ProjectedRasterLayer::referenceGlsl() const {
  const std::string& p = prefix_;
  return "#include \"strata/texel_address.glsl\"\n" + uniform("vec2", p + "_referenceUv") +
         uniform("ivec2", p + "_referenceTexel") + uniform("vec2", p + "_referenceFraction") +
         uniform("vec4", p + "_jacobian");
}

// Texture coordinates and footprint steps of a surface point: within the reach, from its offset to the
// reference (longitude/latitude offsets or the tangent plane's, whichever LocalTextureFrame chose) through
// the polynomial setReference() made, whose derivative gives the steps;
// beyond it, or for a layer never told a reference, through the projection at absolute longitude/latitude.
std::string ProjectedRasterLayer::relativeGlsl() const {
  const std::string& p = prefix_;
  return "#include \"strata/local_offsets.glsl\"\n" + referenceGlsl() + uniform("bool", p + "_tangent") +
         uniform("vec2", p + "_referenceLatitude") + uniform("vec4", p + "_hessianU") +
         uniform("vec4", p + "_hessianV") + uniform("float", p + "_reach") + "vec2 " + p +
         "_offset(SurfacePoint p) {\n"
         "  return " +
         p + "_tangent ? tangentOffset(p.fromReference, " + p +
         "_referenceLatitude) : p.fromReference;\n"
         "}\n"
         "bool " +
         p +
         "_near(SurfacePoint p) {\n"
         "  vec2 d = " +
         p +
         "_offset(p);\n"
         "  return dot(d, d) < " +
         p + "_reach * " + p +
         "_reach;\n"
         "}\n"
         "vec2 " +
         p +
         "_curvature(vec2 d, vec2 step) {\n"
         "  return vec2(dot(mat2(" +
         p + "_hessianU) * d, step), dot(mat2(" + p +
         "_hessianV) * d, step));\n"
         "}\n"
         "vec2 " +
         p +
         "_fromReference(vec2 d) {\n"
         "  return mat2(" +
         p + "_jacobian) * d + 0.5 * " + p +
         "_curvature(d, d);\n"
         "}\n"
         "vec3 " +
         p +
         "_at(SurfacePoint p) {\n"
         "  if (!" +
         p + "_near(p)) return " + p +
         "_coordinates(p.lonlat);\n"
         "  return vec3(" +
         p + "_referenceUv + " + p + "_fromReference(" + p +
         "_offset(p)), 1.0);\n"
         "}\n"
         "TexelAddress " +
         p +
         "_texel(vec3 at, SurfacePoint p) {\n"
         "  if (!" +
         p + "_near(p)) return texelAddressOf(at.xy * vec2(" + p +
         "_size));\n"
         "  return TexelAddress(" +
         p +
         "_referenceTexel,\n"
         "                      " +
         p + "_referenceFraction + " + p + "_fromReference(" + p + "_offset(p)) * vec2(" + p +
         "_size));\n"
         "}\n"
         "vec2 " +
         p +
         "_step(vec3 at, SurfacePoint p, vec2 lonlatStep) {\n"
         "  if (!" +
         p + "_near(p)) return " + p +
         "_absoluteStep(at, p.lonlat, lonlatStep);\n"
         "  vec2 step = " +
         p + "_tangent ? tangentStep(p.fromReference, " + p +
         "_referenceLatitude, lonlatStep)\n"
         "                          : lonlatStep;\n"
         "  return mat2(" +
         p + "_jacobian) * step + " + p + "_curvature(" + p +
         "_offset(p), step);\n"
         "}\n";
}

// The same for a projection affine in longitude and latitude: u and v are the reference's plus the jacobian
// times the point's offset from it, its longitude taken within half a turn of the map's centre, as the
// projection takes it; exact at any distance, so there is no polynomial, no reach and no absolute path.
std::string ProjectedRasterLayer::affineGlsl() const {
  const std::string& p = prefix_;
  return referenceGlsl() + uniform("float", p + "_centreFromReference") + uniform("bool", p + "_relative") + "vec2 " +
         p +
         "_offset(SurfacePoint p) {\n"
         "  vec2 d = " +
         p +
         "_relative ? p.fromReference : p.lonlat;\n"
         "  d.x -= TWO_PI * floor((d.x - " +
         p +
         "_centreFromReference + PI) / TWO_PI);\n"
         "  return mat2(" +
         p +
         "_jacobian) * d;\n"
         "}\n"
         "vec3 " +
         p + "_at(SurfacePoint p) { return vec3(" + p + "_referenceUv + " + p +
         "_offset(p), 1.0); }\n"
         "TexelAddress " +
         p + "_texel(vec3 at, SurfacePoint p) {\n" + "  return TexelAddress(" + p + "_referenceTexel, " + p +
         "_referenceFraction + " + p + "_offset(p) * vec2(" + p +
         "_size));\n"
         "}\n"
         "vec2 " +
         p + "_step(vec3 at, SurfacePoint p, vec2 lonlatStep) { return mat2(" + p + "_jacobian) * lonlatStep; }\n";
}

// Where the layer's texels land, for compositors: texelStepsFunction() and edgeDistanceFunction().
std::string ProjectedRasterLayer::texelGlsl() const {
  const std::string& p = prefix_;
  return "vec4 " + p +
         "_texelSteps(SurfacePoint p) {\n"
         "  vec3 at = " +
         p +
         "_at(p);\n"
         "  if (!insideTexture(at, " +
         p +
         "_repeatX)) return vec4(0.0);\n"
         "  return vec4(" +
         p + "_step(at, p, p.lonlatDx) * vec2(" + p + "_size), " + p + "_step(at, p, p.lonlatDy) * vec2(" + p +
         "_size));\n"
         "}\n"
         "float " +
         p +
         "_edgeDistance(SurfacePoint p) {\n"
         "  vec3 at = " +
         p +
         "_at(p);\n"
         "  if (at.z <= 0.0) return -1.0;\n"
         "  vec4 edges = edgeDistances(" +
         p + "_texel(at, p), " + p +
         "_size);\n"
         "  float across = " +
         p +
         "_repeatX ? 1e30 : min(edges.x, edges.z);\n"
         "  return min(across, min(edges.y, edges.w));\n"
         "}\n";
}

bool ProjectedRasterLayer::oneChannel() const { return !isColour(kind_); }

ProjectionAspect ProjectedRasterLayer::aspect() const {
  return georeference_.projection ? georeference_.projection->aspect() : ProjectionAspect::Other;
}

// The whole strip of twelve faces: a window of one face (healpix::FaceWindow) is sampled as any raster, by
// longitude and latitude relative to the eye, since its nside is beyond what float face points address.
bool ProjectedRasterLayer::onHealpixFaces() const {
  return georeference_.projection && georeference_.projection->type() == healpix::kStripProjectionType &&
         size_.x == 12 * size_.y;
}

void ProjectedRasterLayer::bindSampling(ShaderProgram& program) const {
  program.set(prefix_ + "_projectionA", projection_[0]);
  program.set(prefix_ + "_projectionB", projection_[1]);
  program.set(prefix_ + "_mapToTexture", mapToTexture_);
  program.set(prefix_ + "_scaleOffset", glm::vec2(float(scale_), float(offset_)));
  program.set(prefix_ + "_repeatX", repeatX_ ? 1 : 0);
  program.set(prefix_ + "_size", size_);
  program.set(prefix_ + "_referenceUv", referenceUv_);
  program.set(prefix_ + "_referenceTexel", referenceTexel_);
  program.set(prefix_ + "_referenceFraction", referenceFraction_);
  program.set(prefix_ + "_jacobian", localTerms_[0]);
  program.set(prefix_ + "_hessianU", localTerms_[1]);
  program.set(prefix_ + "_hessianV", localTerms_[2]);
  program.set(prefix_ + "_reach", reach_);
  program.set(prefix_ + "_tangent", tangent_ ? 1 : 0);
  program.set(prefix_ + "_referenceLatitude", referenceLatitude_);
  program.set(prefix_ + "_centreFromReference", centreFromReference_);
  program.set(prefix_ + "_relative", reference_.has_value() ? 1 : 0);
}

}  // namespace strata
