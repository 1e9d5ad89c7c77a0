#include "cutaway.hpp"

#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include <strata/error.hpp>
#include <strata/gl/shader_program.hpp>

namespace strata::composite {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

Cutaway::Shape shapeOf(const std::string& cut) {
  if (cut == "radius") return Cutaway::Shape::Radius;
  if (cut == "box") return Cutaway::Shape::Box;
  return cut == "plane" ? Cutaway::Shape::Plane : Cutaway::Shape::Everywhere;
}

glm::dvec3 unitAt(glm::dvec2 lonlatDegrees) {
  const double lon = lonlatDegrees.x * kDegree, lat = lonlatDegrees.y * kDegree;
  return {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
}

// The plane's normal, planet-fixed: horizontal at the centre, towards the azimuth (east = sin, north = cos),
// so the plane holds the centre, the body's centre and the vertical between them.
glm::dvec3 planeNormal(glm::dvec2 centreDegrees, double azimuthDegrees) {
  const double lon = centreDegrees.x * kDegree, lat = centreDegrees.y * kDegree, azimuth = azimuthDegrees * kDegree;
  const glm::dvec3 east{-std::sin(lon), std::cos(lon), 0.0};
  const glm::dvec3 north{-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat)};
  return std::sin(azimuth) * east + std::cos(azimuth) * north;
}

}  // namespace

std::vector<ParameterDeclaration> Cutaway::parameters() {
  return {
      // everywhere: the peel alone, the simplest view of a stack; the others open a window onto it
      {.name = "cut",
       .type = ParameterType::Choice,
       .defaultValue = std::string("everywhere"),
       .doc = "where the upper layers are cut away: everywhere; radius: within `radius` of `centre`; box: within "
              "`box`; plane: on the `azimuth` side of the vertical plane through `centre`",
       .choices = {"everywhere", "radius", "box", "plane"},
       .live = true},
      // 0, 0: the origin of the body's coordinates, where a test planet's features usually are
      {.name = "centre",
       .type = ParameterType::RealList,
       .defaultValue = std::vector<double>{0.0, 0.0},
       .minimum = -360.0,
       .maximum = 360.0,
       .units = "deg",
       .doc = "[longitude, latitude]: the centre of a radius cut, a point of a plane cut",
       .count = 2,
       .live = true},
      // 100 km: a window the size of a large crater, seen whole from a few hundred kilometres up
      {.name = "radius",
       .type = ParameterType::Real,
       .defaultValue = 1.0e5,
       .minimum = 0.0,
       .maximum = 1.0e8,
       .units = "m",
       .doc = "cut: radius: the distance along the ground from `centre` within which the cut is",
       .live = true},
      // two degrees a side about the origin: some 120 km on Mars, 220 km on Earth
      {.name = "box",
       .type = ParameterType::RealList,
       .defaultValue = std::vector<double>{-1.0, -1.0, 1.0, 1.0},
       .minimum = -360.0,
       .maximum = 360.0,
       .units = "deg",
       .doc = "cut: box: [west, south, east, north]; east may pass 180 to cross the antimeridian",
       .count = 4,
       .live = true},
      // 90: the plane runs north-south through `centre` and the cut takes the east away
      {.name = "azimuth",
       .type = ParameterType::Real,
       .defaultValue = 90.0,
       .minimum = 0.0,
       .maximum = 360.0,
       .units = "deg",
       .doc = "cut: plane: the direction, clockwise from north, of the side the cut takes away",
       .live = true},
      // 0: a step exactly at the region's boundary; give a width of a few vertices to see the cut faces
      {.name = "edge",
       .type = ParameterType::Real,
       .defaultValue = 0.0,
       .minimum = 0.0,
       .maximum = 1.0e7,
       .units = "m",
       .doc = "the width, outside the region, over which the cut's wall slopes from the top surface down to the "
              "peeled one (composite.peeled_surface colours the layers it cuts through); 0: a step",
       .live = true},
  };
}

Cutaway Cutaway::from(const ParameterSet& parameters) {
  const std::vector<double>& centre = parameters.reals("centre");
  const std::vector<double>& box = parameters.reals("box");
  if (box[0] >= box[2] || box[1] >= box[3])
    throw Error(parameters.where("box"),
                "the box's west lies at or east of its east, or its south at or north of its north",
                "give [west, south, east, north], e.g. [170, -10, 190, 10] for a box across the antimeridian");
  return {shapeOf(parameters.string("cut")), {centre[0], centre[1]},     parameters.real("radius"),
          {box[0], box[1], box[2], box[3]},  parameters.real("azimuth"), parameters.real("edge")};
}

void Cutaway::bind(const ShaderProgram& program, const std::string& uniform, double bodyRadius) const {
  program.set(uniform + ".shape", int(shape));
  program.set(uniform + ".centre", glm::vec3(unitAt(centre)));
  program.set(uniform + ".radius", float(radius / bodyRadius));
  program.set(uniform + ".box", glm::vec4(box * kDegree));
  program.set(uniform + ".plane", glm::vec3(planeNormal(centre, azimuth)));
  program.set(uniform + ".edge", float(edge / bodyRadius));
}

}  // namespace strata::composite
