#pragma once
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <strata/plugin/parameter.hpp>

namespace strata {
class ShaderProgram;
}

namespace strata::composite {

// Where composite.layer_peel cuts the upper layers of a stack away ([Kooima 2008, §1.1, ch. 6], layered data
// peeling, which asks for a way to select layers and peel them away): everywhere, within a radius along the
// ground of a point, within a box of longitude and latitude, or on one side of a vertical plane through a
// point. With an edge, the cut's wall slopes from the top surface down to the peeled one over that width
// outside the region, so that the geometry resolves it and the cut faces show; without one it is a step.
struct Cutaway {
  enum class Shape { Everywhere, Radius, Box, Plane };  // the order layer_peel.glsl's Cutaway.shape numbers them

  Shape shape = Shape::Everywhere;
  glm::dvec2 centre{0.0};  // deg: longitude, latitude of the radius's centre, or a point of the plane
  double radius = 0.0;     // m along the ground
  glm::dvec4 box{0.0};     // deg: west, south, east, north
  double azimuth = 0.0;    // deg clockwise from north: the side of the plane the cut takes away
  double edge = 0.0;       // m: the width of the wall's slope outside the region

  // Its parameters, for the node type's declaration, and the cutaway they give (throws strata::Error at a
  // box whose sides are out of order).
  static std::vector<ParameterDeclaration> parameters();
  static Cutaway from(const ParameterSet& parameters);

  // Sets the `uniform` Cutaway struct of layer_peel.glsl in `program` (current); `bodyRadius` in m.
  void bind(const ShaderProgram& program, const std::string& uniform, double bodyRadius) const;
};

}  // namespace strata::composite
