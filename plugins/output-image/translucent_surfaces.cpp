#include "translucent_surfaces.hpp"

#include <algorithm>

#include <strata/gl/shader_program.hpp>
#include <strata/plugin/geometry.hpp>
#include <strata/plugin/layer.hpp>

namespace strata::image {
namespace {

// 1e-5 of the distance (1 m at 100 km): a translucent surface that coincides with the opaque one, drawn by
// another mesh of the same heights, lies within that of it and is not laid over it twice.
constexpr const char* kNearer = "1.00001";

std::string index(std::size_t i) { return std::to_string(i); }

}  // namespace

TranslucentSurfaces::TranslucentSurfaces(const NodeSetup& setup) {
  for (Node* node : setup.inputList("translucent")) geometries_.push_back(node->geometry());
  for (Node* node : setup.inputList("translucent_surface")) layers_.push_back(node->layer());
  if (geometries_.size() != layers_.size())
    throw Error(setup.where,
                std::to_string(geometries_.size()) + " translucent geometries have " + std::to_string(layers_.size()) +
                    " translucent_surface layers",
                "give one colour layer per translucent geometry, in the same order");
}

void TranslucentSurfaces::requestSamples(int samples) {
  for (SurfaceGeometry* geometry : geometries_) geometry->requestSamples(samples);
}

bool TranslucentSurfaces::sampledAs(int samples) const {
  return std::ranges::all_of(geometries_, [samples](const SurfaceGeometry* g) { return g->samples() == samples; });
}

double TranslucentSurfaces::highest() const {
  double highest = 0.0;
  for (const SurfaceGeometry* geometry : geometries_) highest = std::max(highest, geometry->heights().highest);
  return highest;
}

// The colour of translucent surface i at `pixel`, lit as the opaque one is, and its layer's coverage: where
// that has no data the surface is not there (its geometry holds the bare sphere).
std::string TranslucentSurfaces::colourOf(std::size_t i) const {
  const std::string n = index(i);
  return "vec4 translucentColour" + n +
         "(ivec2 pixel, int s) {\n"
         "  vec4 here = texelFetch(translucentSurface" +
         n +
         ", pixel, s);\n"
         "  SurfacePoint p = surfacePointAt(translucentSurface" +
         n +
         ", pixel, s, here);\n"
         "  vec4 v = " +
         layers_[i]->samplingFunction() +
         "(p);\n"
         "  return vec4(v.rgb * lightOn(shadingNormalOf(here, p.normal), p.normal), v.a);\n"
         "}\n";
}

// Each surface's depth (reversed: larger is nearer, 0 where it is not drawn), sorted farthest first, and those
// nearer than the opaque surface laid over it.
std::string TranslucentSurfaces::over() const {
  const std::string n = index(geometries_.size());
  std::string depths, colours;
  for (std::size_t i = 0; i < geometries_.size(); ++i) {
    const std::string k = index(i);
    depths += "  d[" + k + "] = onSurface(texelFetch(translucentSurface" + k +
              ", pixel, s)) ? texelFetch(translucentDepth" + k + ", pixel, s).r : 0.0;\n  order[" + k + "] = " + k +
              ";\n";
    colours += "    if (order[k] == " + k + ") c = translucentColour" + k + "(pixel, s);\n";
  }
  return "vec3 translucentOver(ivec2 pixel, int s, vec3 colour, float depth) {\n"
         "  float d[" +
         n +
         "];\n"
         "  int order[" +
         n + "];\n" + depths + "  for (int i = 1; i < " + n +
         "; ++i)\n"
         "    for (int j = i; j > 0 && d[order[j]] < d[order[j - 1]]; --j) {\n"
         "      int swapped = order[j]; order[j] = order[j - 1]; order[j - 1] = swapped;\n"
         "    }\n"
         "  for (int k = 0; k < " +
         n +
         "; ++k) {\n"
         "    if (d[order[k]] <= depth * " +
         kNearer +
         ") continue;\n"
         "    vec4 c = vec4(0.0);\n" +
         colours +
         "    colour = mix(colour, c.rgb, translucentOpacity * c.a);\n"
         "  }\n"
         "  return colour;\n"
         "}\n";
}

std::string TranslucentSurfaces::glsl() const {
  if (geometries_.empty())
    return "vec3 translucentOver(ivec2 pixel, int s, vec3 colour, float depth) { return colour; }\n";
  std::string code = "uniform float translucentOpacity;\n";
  for (std::size_t i = 0; i < geometries_.size(); ++i)
    code += layers_[i]->glslOnce() + "uniform DeferredBuffer translucentSurface" + index(i) +
            ";\nuniform DeferredBuffer translucentDepth" + index(i) + ";\n" + colourOf(i);
  return code + over();
}

void TranslucentSurfaces::bind(ShaderProgram& program, TextureUnits& units, double opacity) const {
  if (geometries_.empty()) return;
  program.set("translucentOpacity", float(opacity));
  for (std::size_t i = 0; i < geometries_.size(); ++i) {
    const Framebuffer& buffers = geometries_[i]->gbuffer();
    units.bind(program, "translucentSurface" + index(i), buffers.color(0).id());
    units.bind(program, "translucentDepth" + index(i), buffers.depth().id());
    layers_[i]->bind(program, units);
  }
}

}  // namespace strata::image
