#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/plugin/page_demand.hpp>
#include <strata/plugin/port.hpp>
#include <strata/plugin/projection.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class Node;
class ShaderProgram;
struct SourceLocation;
class TextureUnits;

// How a one-channel layer's values vary at the finest scale it bounds them by (RegionalValueLayer::valuesWithin,
// a raster's blocks of texels): the largest range within any one block of the region asked, and that block's
// width, rad (its cap's diameter). With a region's own range it tells how fast the values' range shrinks with the
// region's size: smooth data's as the size, rough data's as its square root. And how sharply the values bend
// there: the largest second derivative along the ground any texel of those blocks shows (the curvature, values
// per rad squared; infinite where not known), and the largest texel, rad, below which the data are bilinear.
struct BlockRelief {
  double range = 0.0;
  double width = 0.0;
  double curvature = std::numeric_limits<double>::infinity();
  double texel = 0.0;
};

// The least and greatest values a one-channel layer returns, as its sampling function returns them
// (heights: metres, after the source's scale and offset).
struct ValueRange {
  double least = 0.0;
  double greatest = 0.0;
  std::optional<BlockRelief> finest;  // valuesWithin() of a layer that knows its values by block: theirs
};

// A layer is a GLSL sampling function over a projection, plus the GPU resources behind it
// (docs/architecture.md, "Nodes and what flows between them"). What only some layers can do besides is in
// small interfaces they opt into (strata/plugin/layer_capabilities.hpp), which consumers ask for with as().
// Consumers paste glslOnce() into their programs after "strata/surface_point.glsl" and call
//   vec4 <samplingFunction()>(SurfacePoint p)
// which returns the value in .rgb (.r for one-channel kinds: heights in metres, already scaled) and the
// coverage weight in .a: 0 outside the data's extent or at nodata, 1 inside, between at edges.
class Layer {
 public:
  virtual ~Layer() = default;

  virtual LayerKind kind() const = 0;
  virtual std::string samplingFunction() const = 0;
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
  // A count that grows whenever the values the sampling function returns may have changed: a page arriving in
  // place of the coarser one that stood in or leaving, a time series moving on, a cut moved; any of a
  // compositor's inputs changing. 0 for a layer whose values never change. Consumers that keep what they sampled
  // (geometry.clipmap's height clipmaps) sample again when it grows. Any thread, once the frame's prepare() is done.
  virtual std::uint64_t revision() const { return 0; }
  // Whether the layer's colours hold light already, as a hillshade's do: an output composes them as they are,
  // not lit a second time by its own light. False for the colours of the ground itself (imagery, data). It may
  // change with the layer's live parameters; outputs ask every frame.
  virtual bool shaded() const { return false; }
  // The capability `Capability` (strata/plugin/layer_capabilities.hpp: texels, a projection's aspect, values by
  // region, HEALPix faces) where this layer offers it, else nullptr.
  template <class Capability>
  const Capability* as() const {
    return dynamic_cast<const Capability*>(this);
  }
};

// The layers `nodes` offer, checked to be of one kind, as whatever blends them needs: throws strata::Error at
// `where` naming the two kinds that differ. `what` names the layers in the message ("layers", "steps").
std::vector<const Layer*> layersOfOneKind(const std::vector<Node*>& nodes, const std::string& what,
                                          const SourceLocation& where);

// The range spanning every one of `layers`' value ranges, within which whatever mixes them stays (a weighted
// average, a blend in time, one laid over another); none where one of them knows none.
std::optional<ValueRange> spanningRange(const std::vector<const Layer*>& layers);

// The revisions of `layers` summed: it grows whenever one of theirs grows. What a compositor's revision() is.
std::uint64_t summedRevision(const std::vector<const Layer*>& layers);

// Turns a node id into a GLSL identifier fragment ("my-dem" -> "my_dem"), for unique function names.
std::string glslIdentifier(const std::string& nodeId);

}  // namespace strata
STRATA_EXPORTS_END
