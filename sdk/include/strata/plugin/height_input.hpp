#pragma once
#include <map>
#include <optional>
#include <strata/export.hpp>
#include <string>
#include <vector>

#include <strata/body.hpp>
#include <strata/error.hpp>
#include <strata/gl/shading_normal.hpp>
#include <strata/plugin/layer.hpp>
#include <strata/plugin/node_type.hpp>
#include <strata/plugin/parameter.hpp>
#include <strata/plugin/parameter_bindings.hpp>
#include <strata/plugin/port.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class Layer;
struct NodeSetup;
struct SphericalCap;

// The heights within a region of the body (HeightInput::within), and their relief at the finest scale the
// height layer knows, where it knows one: geometry scales a region's relief down to its vertex spacing by them.
struct RegionalHeights {
  HeightRange range;
  std::optional<BlockRelief> finest;
};

// The heights a generator is told to trust, as a pipeline writes them. Unset: the height layer's own range
// is exact (a raster's statistics or every texel counted, the analytic bound of procedural relief, the union
// of a compositor's inputs), and a range wider than the terrain only costs culling.
struct HeightBounds {
  std::optional<double> lowest, highest;
};

// What every geometry generator does with its optional `height` input and its optional `lowest` and
// `highest` parameters, declared once so that generators agree and a pipeline switches between them by
// changing one `type` (geometry.icosahedral, geometry.pgm, geometry.healpix).
class HeightInput {
 public:
  // The input port and the two parameters, for the generator's NodeTypeDeclaration.
  static PortDeclaration port();
  static std::vector<ParameterDeclaration> parameters();
  // Both declared on a generator's type: the port as its input, the parameters after those it declared.
  static void declareOn(NodeTypeDeclaration& type);
  // The two parameters, each bound to its member of HeightBounds.
  static const ParameterBindings<HeightBounds>& bounds();

  // Throws strata::Error at `lowest` when both are given and it lies above `highest`.
  explicit HeightInput(const NodeSetup& setup);

  Layer* layer() const { return layer_; }
  // What the generator's deferred buffer holds of the shading normal: the displaced surface's own where there are
  // heights, none on the bare sphere (strata/gl/surface_buffer.hpp).
  ShadingNormal shadingNormal() const { return layer_ ? ShadingNormal::Stored : ShadingNormal::OfTheSphere; }

  // In the generator's open(), once the height layer has opened: settles the heights culling and reference
  // spheres trust. Without a height layer, the bare sphere: {0, 0}. With one, `lowest` and `highest` where
  // given, else the layer's own range (Layer::valueRange) with the sphere's 0, which shows where the layer
  // holds no data. Throws strata::Error at the node when the layer does not know its range and a value is
  // missing, and at `highest`, with the values to set, when given values leave out heights the layer has.
  HeightRange open();
  // What open() settled.
  HeightRange range() const { return range_; }
  // Whether the layer knows its heights over regions (RegionalValueLayer::valuesWithin), once it has placed its texels:
  // then within() tells a plateau from the lowland around it.
  bool boundsRegions() const;
  // The heights within `cap`, where the layer knows them there, within range(); else range(). Culling and
  // levels of detail take a patch's own, so that a patch on a plateau lies on it.
  RegionalHeights within(const SphericalCap& cap) const;

  // The substitutions of a geometry program that samples heights: STRATA_PROGRAM_DEFINES (defining
  // STRATA_HAS_HEIGHT and STRATA_HEIGHT_FUNCTION when there is a layer, STRATA_HEIGHT_FACE_FUNCTION when
  // it can be sampled by HEALPix face point: HealpixFaceLayer::faceSamplingFunction, and
  // STRATA_HEIGHT_SLOPED_FUNCTION when it gives its slopes with its value: SlopedLayer) and STRATA_HEIGHT_LAYER_GLSL.
  std::map<std::string, std::string> substitutions() const;

 private:
  void checkGivenHold(const ValueRange& known) const;

  Layer* layer_;
  HeightBounds given_;  // as given, with a height layer
  HeightRange range_;
  SourceLocation where_, highestWhere_;
};

}  // namespace strata
STRATA_EXPORTS_END
