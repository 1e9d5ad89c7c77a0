#pragma once
#include <strata/export.hpp>
#include <string>
#include <vector>

STRATA_EXPORTS_BEGIN
namespace strata {

// What a layer holds. Heights feed geometry; the other kinds are sampled per screen pixel.
enum class LayerKind { Height, Color, Luminance, Chroma, Normal, Mask, Scalar };

const char* toString(LayerKind kind);
bool parseLayerKind(const std::string& text, LayerKind& kind);

// What travels along an edge of the pipeline graph.
enum class PortType {
  Layer,     // a projected raster with a kind (a source or a compositor's result)
  Geometry,  // a surface rasterised into a deferred texturing buffer (a geometry generator's result)
};

const char* toString(PortType type);

// One input of a node type.
struct PortDeclaration {
  std::string name;
  PortType type = PortType::Layer;
  std::vector<LayerKind> kinds;  // Layer ports: the kinds accepted; empty accepts any
  bool list = false;             // accepts a list of node ids rather than one
  bool optional = false;
  std::string doc;  // one line
};

}  // namespace strata
STRATA_EXPORTS_END
