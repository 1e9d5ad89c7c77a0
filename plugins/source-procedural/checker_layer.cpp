#include "checker_layer.hpp"

#include <cmath>

#include <strata/gl/shader_program.hpp>

namespace strata::procedural {

CheckerLayer::CheckerLayer(const std::string& nodeId, glm::dvec2 anchor, double cell, double radius)
    : prefix_("checker_" + glslIdentifier(nodeId)),
      anchor_(anchor),
      cellsPerRadian_(radius * std::cos(anchor.y) / cell, radius / cell) {}

void CheckerLayer::follow(const View& view) {
  const glm::dvec2 cells = (view.reference - anchor_) * cellsPerRadian_;
  const glm::dvec2 whole = glm::floor(cells);
  referenceFraction_ = glm::vec2(cells - whole);
  referenceParity_ = int(std::fmod(std::abs(whole.x + whole.y), 2.0));
}

// A cell is light where (column + row) is even. The square wave s(x) = +1 on [0, 1), -1 on [1, 2) has the
// triangle wave F(x) = 1 - |1 - (x mod 2)| as its integral, so its mean over a footprint w centred on x is
// (F(x + w/2) - F(x - w/2)) / w; the board is the product of the two axes' waves, filtered axis by axis.
std::string CheckerLayer::glsl() const {
  const std::string& p = prefix_;
  return "uniform vec2 " + p +
         "_fraction;\n"
         "uniform int " +
         p +
         "_parity;\n"
         "uniform vec2 " +
         p +
         "_cellsPerRadian;\n"
         "vec2 " +
         p +
         "_wave(vec2 x) { return 1.0 - abs(1.0 - mod(x, 2.0)); }\n"
         "vec4 " +
         p +
         "(SurfacePoint p) {\n"
         "  vec2 cells = " +
         p + "_fraction + p.fromReference * " + p +
         "_cellsPerRadian;\n"
         "  vec2 w = max((abs(p.lonlatDx) + abs(p.lonlatDy)) * " +
         p +
         "_cellsPerRadian, vec2(1e-4));\n"
         "  vec2 mean = (" +
         p + "_wave(cells + 0.5 * w) - " + p +
         "_wave(cells - 0.5 * w)) / w;\n"
         "  float light = 0.5 + 0.5 * mean.x * mean.y * (" +
         p +
         "_parity == 1 ? -1.0 : 1.0);\n"
         "  return vec4(mix(vec3(0.03), vec3(0.8), light), 1.0);\n"
         "}\n";
}

void CheckerLayer::bind(ShaderProgram& program, TextureUnits&) const {
  program.set(prefix_ + "_fraction", referenceFraction_);
  program.set(prefix_ + "_parity", referenceParity_);
  program.set(prefix_ + "_cellsPerRadian", glm::vec2(cellsPerRadian_));
}

}  // namespace strata::procedural
