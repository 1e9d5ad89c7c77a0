#pragma once
#include <cstdint>
#include <optional>
#include <strata/export.hpp>
#include <string>

#include <strata/plugin/layer.hpp>
#include <strata/plugin/projection.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

struct SphericalCap;

// What some layers can do beyond sampling (strata/plugin/layer.hpp), each a small interface a layer class opts
// into by deriving from it beside Layer. Consumers ask `layer.as<Capability>()` and do without where a
// layer lacks it. A function that names a GLSL function may still return "" where this layer's data do not
// allow it (a time series whose steps lack it, a paged raster that does not lie on HEALPix faces). A new
// capability is a new interface: Layer, and with it every plugin's layers, stays as it is.

// Layers of texels (rasters, and what blends rasters texel for texel), which offer in glsl()
//   vec4 <texelStepsFunction()>(SurfacePoint p)
// the change of their level-0 texel coordinates to the next sample along the footprint's x (.xy) and y (.zw),
// or vec4(0) outside the raster: how well its texels are shaped and how fine they are where they land, which
// composite.projection_quality weighs layers by; and
//   float <edgeDistanceFunction()>(SurfacePoint p)
// the distance in level-0 texels from p to the nearest edge of the raster (none across the seam of one that
// wraps round the body), negative outside it: where composite.overlay_mask feathers an overlay's extent.
class TexelledLayer {
 public:
  virtual ~TexelledLayer() = default;
  virtual std::string texelStepsFunction() const = 0;
  virtual std::string edgeDistanceFunction() const = 0;
};

// Layers sampled through a projection: which region of the body it samples best (ProjectionAspect), once
// the layer's node has created its GPU resources (rasters are placed then). composite.projection_quality
// weighs by latitude with it.
class ProjectedLayer {
 public:
  virtual ~ProjectedLayer() = default;
  virtual ProjectionAspect aspect() const = 0;
};

// One-channel layers that know their values region by region, once their node has placed its texels: bounds
// of what they return for points within `cap`, 0 included where some of the cap holds no data, within
// Layer::valueRange(); none where they do not know them there. Geometry takes a patch's heights from them,
// so that a patch on a plateau is measured on the plateau (docs/geometry.md, "Height ranges"), and widens the
// cap by the reach of its samples' footprints beyond the patch.
class RegionalValueLayer {
 public:
  virtual ~RegionalValueLayer() = default;
  virtual std::optional<ValueRange> valuesWithin(const SphericalCap& cap) const = 0;
};

// Layers whose texels are the faces of a HEALPix pyramid (strata/plugin/healpix_pyramid.hpp), which can be sampled by
// face point with no projection on the way (geometry.healpix does so):
//   vec4 <faceSamplingFunction()>(vec3 point, float footprint)
// point = (face, x, y) as healpix::FacePoint has them, footprint = the face-point distance to the next
// sample; it returns what Layer::samplingFunction() returns. faceNodeValues() bounds their values over node
// (level, ix, iy) of base face `face`'s quadtree (2^level nodes a side, ix along x, iy along y, as
// geometry.healpix numbers them): bounds of whatever sampling reads for its points, 0 included where some of
// it holds no data (generators take the sphere there); none where the layer does not know them.
class HealpixFaceLayer {
 public:
  virtual ~HealpixFaceLayer() = default;
  virtual std::string faceSamplingFunction() const = 0;
  virtual std::optional<ValueRange> faceNodeValues(int face, int level, std::int64_t ix, std::int64_t iy) const = 0;
};

// One-channel layers that give their value's slopes with the value, from the texels one sample filters:
//   vec4 <slopedSamplingFunction()>(SurfacePoint p)
// returns the value in .r, its change per radian along the ground east (.g) and north (.b), and the coverage
// in .a, as Layer::samplingFunction() has them. Relief and slopes (strata/plugin/height_slopes.hpp) take one
// such sample where other layers take five.
class SlopedLayer {
 public:
  virtual ~SlopedLayer() = default;
  virtual std::string slopedSamplingFunction() const = 0;
};

// What a layer offers through its capabilities, "" (or ProjectionAspect::Other) where it lacks them: for
// consumers that paste the functions or pass them on.
inline std::string texelStepsFunctionOf(const Layer& layer) {
  const auto* texels = layer.as<TexelledLayer>();
  return texels ? texels->texelStepsFunction() : std::string();
}
inline std::string edgeDistanceFunctionOf(const Layer& layer) {
  const auto* texels = layer.as<TexelledLayer>();
  return texels ? texels->edgeDistanceFunction() : std::string();
}
inline std::string slopedSamplingFunctionOf(const Layer& layer) {
  const auto* sloped = layer.as<SlopedLayer>();
  return sloped ? sloped->slopedSamplingFunction() : std::string();
}
inline ProjectionAspect aspectOf(const Layer& layer) {
  const auto* projected = layer.as<ProjectedLayer>();
  return projected ? projected->aspect() : ProjectionAspect::Other;
}
inline std::string faceSamplingFunctionOf(const Layer& layer) {
  const auto* faces = layer.as<HealpixFaceLayer>();
  return faces ? faces->faceSamplingFunction() : std::string();
}

}  // namespace strata
STRATA_EXPORTS_END
