#pragma once
#include <cstdint>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/page_demand.hpp>
#include <strata/port.hpp>
#include <strata/projection.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class Node;
class ShaderProgram;
struct SourceLocation;
struct SphericalCap;
class TextureUnits;

// The least and greatest values a one-channel layer returns, as its sampling function returns them
// (heights: metres, after the source's scale and offset).
struct ValueRange {
  double least = 0.0;
  double greatest = 0.0;
};

// A layer is a GLSL sampling function over a projection, plus the GPU resources behind it
// (docs/architecture.md, "Nodes and what flows between them").
// Consumers paste glslOnce() into their programs after "strata/surface_point.glsl" and call
//   vec4 <samplingFunction()>(SurfacePoint p)
// which returns the value in .rgb (.r for one-channel kinds: heights in metres, already scaled) and the
// coverage weight in .a: 0 outside the data's extent or at nodata, 1 inside, between at edges.
class Layer {
 public:
  virtual ~Layer() = default;

  virtual LayerKind kind() const = 0;
  virtual std::string samplingFunction() const = 0;
  // Layers of texels also offer, in glsl(),
  //   vec4 <texelStepsFunction()>(SurfacePoint p)
  // the change of their level-0 texel coordinates to the next sample along the footprint's x (.xy) and y
  // (.zw), or vec4(0) outside the raster: how well its texels are shaped and how fine they are where they
  // land, which composite.projection_quality weighs layers by. Empty for layers without texels (procedural).
  virtual std::string texelStepsFunction() const { return {}; }
  // And
  //   float <edgeDistanceFunction()>(SurfacePoint p)
  // the distance in level-0 texels from p to the nearest edge of the raster (none across the seam of one that
  // wraps round the body), negative outside it: where composite.overlay_mask feathers an overlay's extent.
  virtual std::string edgeDistanceFunction() const { return {}; }
  // Which region of the body its projection samples best (ProjectionAspect), once its node has created its
  // GPU resources (rasters are placed then); Other for layers with none (procedural, composed).
  virtual ProjectionAspect aspect() const { return ProjectionAspect::Other; }
  // The layer's GLSL, its inputs' glslOnce() included, for consumers to paste: what they call and its
  // uniforms, named after the node (glslIdentifier).
  virtual std::string glsl() const = 0;
  // glsl() guarded so that a program it is pasted into twice defines it once: a layer two consumers share
  // (one colour layer under two compositors of one frame). What consumers paste.
  std::string glslOnce() const;
  // Binds the layer's textures and sets its uniforms in `program` (current), on the GL thread.
  virtual void bind(ShaderProgram& program, TextureUnits& units) const = 0;
  // How much the pages behind the layer are wanted (PageDemand), so that a time series shows two of its
  // steps and lets the others idle: paged layers tell their cache, compositors pass it on to their inputs,
  // layers without pages ignore it. Any thread (nodes call it from prepare()); the next frame follows it.
  virtual void setPageDemand(PageDemand demand) const { (void)demand; }
  // The values the layer can return, once its node has opened, where its source knows them for certain
  // (geometry uses them to check what it may cull); none where it does not.
  virtual std::optional<ValueRange> valueRange() const { return std::nullopt; }
  // The values the layer can return for points within `cap` (one-channel kinds, once its node has placed its
  // texels): bounds, 0 included where some of the cap holds no data, within valueRange(). Geometry takes a
  // patch's heights from them, so that a patch on a plateau is measured on the plateau (docs/geometry.md,
  // "Height ranges"), and widens the cap by the reach of its samples' footprints beyond the patch. None where
  // the layer does not know them; generators then take valueRange().
  virtual std::optional<ValueRange> valuesWithin(const SphericalCap& cap) const {
    (void)cap;
    return std::nullopt;
  }
  // Layers whose texels are the faces of a HEALPix pyramid (strata/healpix_pyramid.hpp) can also be sampled
  // by face point, with no projection on the way (geometry.healpix does so):
  //   vec4 <faceSamplingFunction()>(vec3 point, float footprint)
  // point = (face, x, y) as healpix::FacePoint has them, footprint = the face-point distance to the next
  // sample; it returns what samplingFunction() returns. Empty for other layers.
  virtual std::string faceSamplingFunction() const { return {}; }
  // Such layers may also bound their values over node (level, ix, iy) of base face `face`'s quadtree (2^level
  // nodes a side, ix along x, iy along y, as geometry.healpix numbers them): bounds of whatever sampling reads
  // for its points, 0 included where some of it holds no data (generators take the sphere there). Empty
  // where the layer does not know them.
  virtual std::optional<ValueRange> faceNodeValues(int face, int level, std::int64_t ix, std::int64_t iy) const {
    (void)face, (void)level, (void)ix, (void)iy;
    return std::nullopt;
  }
};

// The layers `nodes` offer, checked to be of one kind, as whatever blends them needs: throws strata::Error at
// `where` naming the two kinds that differ. `what` names the layers in the message ("layers", "steps").
std::vector<const Layer*> layersOfOneKind(const std::vector<Node*>& nodes, const std::string& what,
                                          const SourceLocation& where);

// The range spanning every one of `layers`' value ranges, within which whatever mixes them stays (a weighted
// average, a blend in time, one laid over another); none where one of them knows none.
std::optional<ValueRange> spanningRange(const std::vector<const Layer*>& layers);

// Turns a node id into a GLSL identifier fragment ("my-dem" -> "my_dem"), for unique function names.
std::string glslIdentifier(const std::string& nodeId);

}  // namespace strata
STRATA_EXPORTS_END
