#pragma once
#include <strata/export.hpp>
#include <map>
#include <string>
#include <vector>

#include <strata/error.hpp>
#include <strata/parameter.hpp>
#include <strata/port.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

class Layer;
struct NodeSetup;

// The heights a geometry generator's surface holds, in m above the body's radius. Culling and reference
// spheres trust them: terrain outside them may be cut off.
struct HeightRange {
  double lowest = 0.0;
  double highest = 0.0;
};

// What every geometry generator does with its optional `height` input and its `lowest` and `highest`
// parameters, declared once so that generators agree and a pipeline switches between them by changing one
// `type` (geometry.icosahedral, geometry.pgm).
class HeightInput {
 public:
  // The input port and the two parameters, for the generator's NodeTypeDeclaration.
  static PortDeclaration port();
  static std::vector<ParameterDeclaration> parameters();

  // Throws strata::Error at `lowest` when it lies above `highest`. Without a height layer the surface is
  // the bare sphere, range {0, 0}, whatever the parameters say.
  explicit HeightInput(const NodeSetup& setup);

  Layer* layer() const { return layer_; }
  HeightRange range() const { return range_; }

  // In the generator's open(): throws strata::Error at `highest`, with the values to set, when the height
  // layer knows its heights and they leave the range.
  void checkLayerWithin() const;

  // The substitutions of a geometry program that samples heights: STRATA_PROGRAM_DEFINES (defining
  // STRATA_HAS_HEIGHT and STRATA_HEIGHT_FUNCTION when there is a layer, and STRATA_HEIGHT_FACE_FUNCTION when
  // it can be sampled by HEALPix face point: Layer::faceSamplingFunction) and STRATA_HEIGHT_LAYER_GLSL.
  std::map<std::string, std::string> substitutions() const;

 private:
  Layer* layer_;
  HeightRange range_;
  SourceLocation highestWhere_;
};

}  // namespace strata
STRATA_EXPORTS_END
