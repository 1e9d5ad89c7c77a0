#include "cutaway.hpp"

#include <cmath>
#include <numbers>

#include <glm/vec3.hpp>

#include <strata/error.hpp>
#include <strata/gl/shader_program.hpp>
#include <strata/plugin/parameter_bindings.hpp>

namespace strata::composite {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

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

// The cutaway as a pipeline writes it, each default's reason beside it.
struct CutawaySettings {
  // everywhere: the peel alone, the simplest view of a stack; the others open a window onto it
  Cutaway::Shape shape = Cutaway::Shape::Everywhere;
  // 0, 0: the origin of the body's coordinates, where a test planet's features usually are
  std::vector<double> centre{0.0, 0.0};
  double radius = 1.0e5;  // 100 km: a window the size of a large crater, seen whole from a few hundred kilometres up
  // two degrees a side about the origin: some 120 km on Mars, 220 km on Earth
  std::vector<double> box{-1.0, -1.0, 1.0, 1.0};
  double azimuth = 90.0;  // the plane runs north-south through `centre` and the cut takes the east away
  double edge = 0.0;  // a step exactly at the region's boundary; give a width of a few vertices to see the cut faces
};

// Every parameter is live: the cutaway changes the next frame.
const ParameterBindings<CutawaySettings>& cutawayParameters() {
  using S = CutawaySettings;
  static const auto bindings =
      ParameterBindings<S>()
          .choice(&S::shape,
                  {.name = "cut",
                   .doc = "where the upper layers are cut away: everywhere; radius: within `radius` of `centre`; box: "
                          "within `box`; plane: on the `azimuth` side of the vertical plane through `centre`",
                   .live = true},
                  {{"everywhere", Cutaway::Shape::Everywhere},
                   {"radius", Cutaway::Shape::Radius},
                   {"box", Cutaway::Shape::Box},
                   {"plane", Cutaway::Shape::Plane}})
          .add(&S::centre, {.name = "centre",
                            .minimum = -360.0,
                            .maximum = 360.0,
                            .units = "deg",
                            .doc = "[longitude, latitude]: the centre of a radius cut, a point of a plane cut",
                            .count = 2,
                            .live = true})
          .add(&S::radius, {.name = "radius",
                            .minimum = 0.0,
                            .maximum = 1.0e8,
                            .units = "m",
                            .doc = "cut: radius: the distance along the ground from `centre` within which the cut is",
                            .live = true})
          .add(&S::box, {.name = "box",
                         .minimum = -360.0,
                         .maximum = 360.0,
                         .units = "deg",
                         .doc = "cut: box: [west, south, east, north]; east may pass 180 to cross the antimeridian",
                         .count = 4,
                         .live = true})
          .add(&S::azimuth, {.name = "azimuth",
                             .minimum = 0.0,
                             .maximum = 360.0,
                             .units = "deg",
                             .doc = "cut: plane: the direction, clockwise from north, of the side the cut takes away",
                             .live = true})
          .add(&S::edge, {.name = "edge",
                          .minimum = 0.0,
                          .maximum = 1.0e7,
                          .units = "m",
                          .doc = "the width, outside the region, over which the cut's wall slopes from the top "
                                 "surface down to the peeled one (composite.peeled_surface colours the layers it "
                                 "cuts through); 0: a step",
                          .live = true});
  return bindings;
}

}  // namespace

std::vector<ParameterDeclaration> Cutaway::parameters() { return cutawayParameters().declarations(); }

Cutaway Cutaway::from(const ParameterSet& parameters) {
  const CutawaySettings settings = cutawayParameters().read(parameters);
  const std::vector<double>& centre = settings.centre;
  const std::vector<double>& box = settings.box;
  if (box[0] >= box[2] || box[1] >= box[3])
    throw Error(cutawayParameters().where(parameters, &CutawaySettings::box),
                "the box's west lies at or east of its east, or its south at or north of its north",
                "give [west, south, east, north], e.g. [170, -10, 190, 10] for a box across the antimeridian");
  return {settings.shape,   {centre[0], centre[1]}, settings.radius, {box[0], box[1], box[2], box[3]},
          settings.azimuth, settings.edge};
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
