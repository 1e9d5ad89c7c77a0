// strata project: what Strata's projection of a CRS, built in or a plugin's, makes of points, so that a
// projection's author can hold its C++ forward and inverse against PROJ's (gdaltransform) without writing
// a program (docs/sdk/writing-a-projection.md, "Testing it").
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include <strata/crs.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "command_options.hpp"
#include "commands.hpp"

namespace strata::cli {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

struct ProjectOptions {
  std::string crs;
  std::string points = "-";  // a file of points, or standard input
  bool inverse = false;
};

// Two numbers at the start of `line`, as gdaltransform reads its input: further columns are ignored.
std::optional<glm::dvec2> readPoint(const std::string& line) {
  std::istringstream stream(line);
  glm::dvec2 point;
  if (stream >> point.x >> point.y) return point;
  return std::nullopt;
}

// Forward: longitude and latitude in degrees to map coordinates in the CRS's units. Inverse: back.
std::optional<glm::dvec2> transform(const Projection& projection, glm::dvec2 point, bool inverse) {
  if (!inverse) return projection.forward(point * kDegree);
  const std::optional<glm::dvec2> lonlat = projection.inverse(point);
  if (lonlat) return *lonlat / kDegree;
  return std::nullopt;
}

void project(const ProjectOptions& options) {
  PluginRegistry registry;
  registry.loadDirectories(defaultPluginDirectories());
  const std::unique_ptr<Projection> projection = projectionOfCrs(registry, options.crs, {"strata project"});
  std::ifstream file;
  if (options.points != "-") {
    file.open(options.points);
    if (!file) throw Error({options.points}, "cannot open the points file", "check its name and permissions");
  }
  std::istream& input = options.points == "-" ? std::cin : file;
  const std::string name = options.points == "-" ? "standard input" : options.points;
  std::string line;
  for (int number = 1; std::getline(input, line); ++number) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::optional<glm::dvec2> point = readPoint(line);
    if (!point)
      throw Error({name, number, 1}, "not two numbers: '" + line + "'",
                  options.inverse ? "write X Y in the CRS's units, one point a line"
                                  : "write LON LAT in degrees, one point a line");
    if (const std::optional<glm::dvec2> result = transform(*projection, *point, options.inverse))
      std::printf("%.17g %.17g\n", result->x, result->y);
    else
      std::printf("outside\n");  // the projection does not map this point
  }
}

}  // namespace

void addProjectCommand(CLI::App& app, int& exitCode) {
  auto options = std::make_shared<ProjectOptions>();
  CLI::App* command = app.add_subcommand(
      "project", "print what Strata's projection of a CRS makes of points (LON LAT in degrees, a line each)");
  command->add_option("crs", options->crs, "the CRS: a PROJ string, WKT or EPSG:code")->required();
  command->add_option("points", options->points, "a file of points, or - for standard input (the default)");
  command->add_flag("--inverse", options->inverse, "map coordinates X Y to LON LAT in degrees instead");
  command->callback([options, &exitCode] { exitCode = reportingErrors([&] { project(*options); }); });
}

}  // namespace strata::cli
