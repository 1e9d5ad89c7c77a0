#include "sector_culling.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace strata::clipmap {
namespace {

// The sides of a view's frustum in eye space, each inside where its value at a point is at least 0: ahead of the
// eye, and within the frame's edges widened by the margin.
struct Frustum {
  glm::dvec2 tangents;

  std::array<double, 5> sides(const glm::dvec3& p) const {
    const double ahead = -p.z;
    return {ahead, p.x + tangents.x * ahead, -p.x + tangents.x * ahead, p.y + tangents.y * ahead,
            -p.y + tangents.y * ahead};
  }
};

// A wedge of the rings: theta~ from `inner` to `outer`, phi~ from `first` to `last`.
struct Wedge {
  double inner, outer, first, last;
};

// The colatitude of the wedge's outer points. The outer ring, a small circle about the nadir, bows out beyond the
// great circles between its points: they are put where those great circles pass through the ring's farthest points,
// tan(theta') = tan(theta) / cos(half their spacing). Within a quarter turn of the nadir (mayShow draws the rest).
double bowedOuter(const Wedge& wedge) {
  return std::atan(std::tan(wedge.outer) / std::cos(0.25 * (wedge.last - wedge.first)));
}

// The wedge's 3 x 3 directions: its corners, its edges' midpoints and its middle, whose spherical hull holds it.
std::array<glm::dvec3, 9> wedgeDirections(const Wedge& wedge) {
  const double spacing = 0.5 * (wedge.last - wedge.first);
  const std::array<double, 3> colatitudes = {wedge.inner, 0.5 * (wedge.inner + wedge.outer), bowedOuter(wedge)};
  std::array<glm::dvec3, 9> directions;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      directions[3 * i + j] = hemisphereDirection(colatitudes[i], wedge.first + double(j) * spacing);
  return directions;
}

// The angle from any point of the wedge to the nearest of its 3 x 3 directions, at most: half a cell's spans, the
// outer cells' to the bowed points. Within a quarter turn of the nadir, where sin theta~ grows with theta~.
double cellReach(const Wedge& wedge) {
  const double outer = bowedOuter(wedge);
  return 0.5 * (outer - 0.5 * (wedge.inner + wedge.outer)) + 0.25 * std::sin(outer) * (wedge.last - wedge.first);
}

// A view's frustum, and what it takes to place a wedge's shell in it.
struct WedgeView {
  glm::dmat3 localToPlanet, localToEye;
  glm::dvec3 eyeLocal;  // the eye in the east-north-up frame at the centre: (0, 0, its distance)
  Frustum frustum;
  double radius;
  double ringSpacing;  // the rings' per rad of theta~: the heights' footprint
  const HeightsOver& heightsOver;

  // Whether the shell over `wedge` between radii `low` and `high` may show: its directions at `low`, and at `high`
  // lifted so that their hull holds the sphere between them (by 1 / cos of the cell's reach).
  bool shellMayShow(const Wedge& wedge, double low, double high) const {
    const double lifted = high / std::cos(cellReach(wedge));
    std::array<bool, 5> allOutside;
    allOutside.fill(true);
    for (const glm::dvec3& d : wedgeDirections(wedge))
      for (const double r : {low, lifted}) {
        const std::array<double, 5> sides = frustum.sides(localToEye * (r * d - eyeLocal));
        for (std::size_t s = 0; s < sides.size(); ++s) allOutside[s] = allOutside[s] && sides[s] < 0.0;
      }
    return std::none_of(allOutside.begin(), allOutside.end(), [](bool outside) { return outside; });
  }

  // Whether `wedge` may show, between the heights over it, the shell cut at the eye's radius where it holds it:
  // about the eye a wedge's shell is a column through it, whose parts below and above the eye each lie outside a
  // side of a frustum that looks neither straight down nor straight up, where the column as a whole lies outside
  // none. A wedge beyond a quarter turn from the nadir, or too wide to bound by its 3 x 3 directions, always may.
  bool mayShow(const Wedge& wedge) const {
    if (wedge.outer >= 0.5 * std::numbers::pi || cellReach(wedge) >= 0.25 * std::numbers::pi) return true;
    std::array<glm::dvec3, 9> directions = wedgeDirections(wedge);
    for (glm::dvec3& d : directions) d = localToPlanet * d;
    const HeightRange heights =
        heightsOver(capAround(directions).widened(cellReach(wedge) + 2.0 * ringSpacing * wedge.outer));
    const double low = radius + heights.lowest, high = radius + heights.highest, eye = eyeLocal.z;
    if (low >= eye || high <= eye) return shellMayShow(wedge, low, high);
    return shellMayShow(wedge, low, eye) || shellMayShow(wedge, eye, high);
  }
};

void append(std::vector<IndexRange>& ranges, const IndexRange& range) {
  if (!ranges.empty() && ranges.back().first + ranges.back().count == range.first)
    ranges.back().count += range.count;
  else
    ranges.push_back(range);
}

}  // namespace

std::vector<IndexRange> visibleRanges(const HemisphereRings& mesh, const DrawnLevels& drawn, const View& view,
                                      double radius, const HeightsOver& heightsOver, double marginPixels) {
  const glm::dmat3 localToPlanet = glm::transpose(planetToLocal(view.reference));
  const int m = mesh.settings.ringsPerLevel;
  const WedgeView seen{localToPlanet,
                       view.planetToEye * localToPlanet,
                       glm::dvec3(0.0, 0.0, glm::length(view.eye)),
                       Frustum{view.halfFrameTangents() * (1.0 + 2.0 * marginPixels / double(view.height))},
                       radius,
                       1.0 - std::exp2(-1.0 / m),
                       heightsOver};
  std::vector<IndexRange> ranges;
  for (int level = drawn.coarsest; level <= drawn.finest; ++level)
    for (int sector = 0; sector < mesh.sectors; ++sector) {
      const Wedge wedge{ringColatitude((level + 1) * m, m), ringColatitude(level * m, m), sectorAzimuth(mesh, sector),
                        sectorAzimuth(mesh, sector + 1)};
      if (seen.mayShow(wedge)) append(ranges, sectorRange(mesh, level, sector));
    }
  append(ranges, mesh.caps[std::size_t(drawn.finest)]);
  return ranges;
}

}  // namespace strata::clipmap
