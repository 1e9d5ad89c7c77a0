#pragma once
#include <string>
#include <vector>

#include <strata/plugin/node.hpp>

namespace strata {
class ShaderProgram;
class SurfaceGeometry;
class TextureUnits;
}  // namespace strata

namespace strata::image {

// Surfaces output.image lays translucent over its geometry (issue 8, "show upper layers translucent over
// lower ones with correct ordering"; [Kooima 2008, ch. 6], layered data peeling, which asks how to show
// several layers at once where upper ones would occlude lower ones): each a geometry of its own, drawn into its
// own deferred buffer with the same view, and coloured by one layer. Per pixel, those nearer than the
// opaque surface are laid over it farthest first, each hiding `opacity` of what lies behind it, so the
// order is right however the surfaces cross and wherever the camera is.
class TranslucentSurfaces {
 public:
  // The `translucent` geometries and their `translucent_surface` layers, one each (throws strata::Error at
  // the node when the counts differ).
  explicit TranslucentSurfaces(const NodeSetup& setup);

  // Asks each geometry for `samples` per pixel (SurfaceGeometry::requestSamples); whether each draws `samples`.
  void requestSamples(int samples);
  bool sampledAs(int samples) const;
  // The highest of the geometries' heights (m above the body's radius), 0 where there are none.
  double highest() const;

  // What composite.frag's STRATA_TRANSLUCENT_GLSL becomes: the layers' GLSL and
  //   vec3 translucentOver(ivec2 pixel, int s, vec3 colour, float depth)
  // for sample `s` of `pixel`.
  std::string glsl() const;
  // Binds each geometry's buffers and layer, and the opacity: how much of what lies behind each it hides.
  void bind(ShaderProgram& program, TextureUnits& units, double opacity) const;

 private:
  std::string colourOf(std::size_t i) const;
  std::string over() const;

  std::vector<SurfaceGeometry*> geometries_;
  std::vector<const Layer*> layers_;
};

}  // namespace strata::image
