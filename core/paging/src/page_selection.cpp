#include "page_selection.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include <strata/plugin/projection.hpp>

namespace strata::paging {
namespace {

constexpr int kSamples = 5;  // per side: a page's corners, edge midpoints and quarter points
// Sampled points stand for a curved page, and terrain rises above the sphere: a point counts as above
// the horizon up to 1% of R^2 below the horizon plane, and as in view 10% outside the frustum.
constexpr double kHorizonSlack = 0.01;
constexpr double kFrustumSlack = 0.1;
// Bounds the traversal should the view ask for more pages than any cache holds.
constexpr std::size_t kMostWanted = 8192;

struct Viewing {
  const Body& body;
  const View& view;
  double tanHalfHeight;
  double tanHalfWidth;
  double pixelAngle;                   // rad per pixel, vertically
  glm::dvec2 nadir;                    // lon/lat (rad) below the eye
  double altitude;                     // m above the ground level distances are measured to
  double groundRadius;                 // m: that level's sphere
  double lowestRadius, highestRadius;  // m: the spheres the terrain lies between
};

Viewing viewingOf(const Body& body, const View& view, const HeightRange& terrain) {
  const glm::dvec2 halfFrame = view.halfFrameTangents();
  const double r = glm::length(view.eye), ground = groundLevelNear(terrain, r - body.radius);
  return {body,
          view,
          halfFrame.y,
          halfFrame.x,
          view.verticalFov / double(std::max(1, view.height)),
          {std::atan2(view.eye.y, view.eye.x), std::asin(std::clamp(view.eye.z / r, -1.0, 1.0))},
          std::abs(r - body.radius - ground),
          body.radius + ground,
          body.radius + terrain.lowest,
          body.radius + terrain.highest};
}

struct PageBounds {
  bool visible = false;
  bool refine = false;
  double distance = std::numeric_limits<double>::max();
};

// Level texel coordinates to map coordinates through the geotransform (a level-l texel is 2^l raster
// texels; the raster's own edge bounds the last one).
glm::dvec2 mapOf(const SelectableLayer& layer, int level, glm::dvec2 texel) {
  const std::array<double, 6>& t = layer.georeference->geotransform;
  const double scale = std::ldexp(1.0, level);
  const double x = std::min(texel.x * scale, double(layer.pyramid->width()));
  const double y = std::min(texel.y * scale, double(layer.pyramid->height()));
  return {t[0] + x * t[1], t[3] + y * t[5]};
}

// Whether the points lie outside one and the same plane of the view frustum.
bool outsideFrustum(const std::vector<glm::dvec3>& eyePoints, const Viewing& viewing) {
  const double tx = viewing.tanHalfWidth * (1.0 + kFrustumSlack), ty = viewing.tanHalfHeight * (1.0 + kFrustumSlack);
  const auto allOutside = [&](auto outside) { return std::ranges::all_of(eyePoints, outside); };
  return allOutside([](const glm::dvec3& q) { return q.z >= 0.0; }) ||
         allOutside([&](const glm::dvec3& q) { return q.x < q.z * tx; }) ||
         allOutside([&](const glm::dvec3& q) { return q.x > -q.z * tx; }) ||
         allOutside([&](const glm::dvec3& q) { return q.y < q.z * ty; }) ||
         allOutside([&](const glm::dvec3& q) { return q.y > -q.z * ty; });
}

// The page's point nearest the point below the eye, in level texels: the nadir's own texel where the page
// holds it (then the page is as near as the altitude), else the nadir's texel clamped into the page, of
// the nadir's texel positions one period apart (a wrapping raster) the nearest. The sample grid alone can
// miss it: a page across the antimeridian from the eye, whose nearest point lies on its edge between two
// samples 45 degrees apart, was taken for one below the horizon and drawn from a coarser level.
struct NearestPoint {
  glm::dvec2 texel;
  bool nadir;  // the page holds the point below the eye
};

std::optional<NearestPoint> nearestToNadir(const SelectableLayer& layer, const PageKey& key, glm::dvec2 low,
                                           glm::dvec2 high, const Viewing& viewing) {
  const std::optional<glm::dvec2> map = layer.georeference->projection->forward(viewing.nadir);
  if (!map) return std::nullopt;
  const std::array<double, 6>& t = layer.georeference->geotransform;
  const double scale = std::ldexp(1.0, key.level);
  glm::dvec2 texel((map->x - t[0]) / t[1] / scale, (map->y - t[3]) / t[5] / scale);
  if (layer.wrapX) {
    const double period = double(layer.pyramid->width()) / scale, middle = 0.5 * (low.x + high.x);
    texel.x = middle + std::remainder(texel.x - middle, period);
  }
  const glm::dvec2 clamped = glm::clamp(texel, low, high);
  return NearestPoint{clamped, clamped == texel};
}

PageBounds boundsOf(const SelectableLayer& layer, const PageKey& key, const Viewing& viewing) {
  const PagePyramid& pyramid = *layer.pyramid;
  const glm::dvec2 low(key.column * kPagePayload, key.row * kPagePayload);
  const glm::dvec2 high(std::min(low.x + kPagePayload, double(pyramid.levelWidth(key.level))),
                        std::min(low.y + kPagePayload, double(pyramid.levelHeight(key.level))));
  const glm::dvec2 spacing = (high - low) / double(kSamples - 1);
  std::array<std::optional<glm::dvec3>, kSamples * kSamples> points;
  std::vector<glm::dvec3> eyePoints;
  PageBounds bounds;
  bool aboveHorizon = false;
  const double r2 = viewing.body.radius * viewing.body.radius;
  // A point of the page, by its unit normal: the terrain above it, anywhere between its lowest and highest,
  // may be what is in view.
  const auto consider = [&](const glm::dvec3& n) {
    eyePoints.push_back(viewing.view.toEye(viewing.lowestRadius * n));
    eyePoints.push_back(viewing.view.toEye(viewing.highestRadius * n));
    aboveHorizon = aboveHorizon || glm::dot(viewing.body.radius * n, viewing.view.eye) >= r2 * (1.0 - kHorizonSlack);
    bounds.distance = std::min(bounds.distance, glm::length(viewing.groundRadius * n - viewing.view.eye));
  };
  for (int j = 0; j < kSamples; ++j)
    for (int i = 0; i < kSamples; ++i) {
      const std::optional<glm::dvec2> lonlat =
          layer.georeference->projection->inverse(mapOf(layer, key.level, low + spacing * glm::dvec2(i, j)));
      if (!lonlat) continue;
      const glm::dvec3 n = unitNormal(lonlat->x, lonlat->y);
      points[std::size_t(j * kSamples + i)] = viewing.body.radius * n;
      consider(n);
    }
  const std::optional<NearestPoint> nearest = nearestToNadir(layer, key, low, high, viewing);
  const bool nadir = nearest && nearest->nadir;
  if (nadir) bounds.distance = std::min(bounds.distance, viewing.altitude);
  if (const std::optional<glm::dvec2> lonlat =
          nearest ? layer.georeference->projection->inverse(mapOf(layer, key.level, nearest->texel)) : std::nullopt)
    consider(unitNormal(lonlat->x, lonlat->y));
  bounds.visible = !eyePoints.empty() && (nadir || aboveHorizon) && !outsideFrustum(eyePoints, viewing);
  // The largest ground distance between neighbouring samples, per texel between them.
  double texelSize = 0.0;
  for (int j = 0; j < kSamples; ++j)
    for (int i = 0; i < kSamples; ++i) {
      const auto& p = points[std::size_t(j * kSamples + i)];
      if (!p) continue;
      if (const auto& east = i + 1 < kSamples ? points[std::size_t(j * kSamples + i + 1)] : std::nullopt; east)
        texelSize = std::max(texelSize, glm::length(*east - *p) / std::max(spacing.x, 1.0));
      if (const auto& south = j + 1 < kSamples ? points[std::size_t((j + 1) * kSamples + i)] : std::nullopt; south)
        texelSize = std::max(texelSize, glm::length(*south - *p) / std::max(spacing.y, 1.0));
    }
  bounds.refine = key.level > 0 && texelSize > bounds.distance * viewing.pixelAngle;
  return bounds;
}

void addChildren(const PagePyramid& pyramid, const PageKey& key, std::vector<PageKey>& out) {
  for (int row = 2 * key.row; row < 2 * key.row + 2; ++row)
    for (int column = 2 * key.column; column < 2 * key.column + 2; ++column)
      if (const PageKey child{key.level - 1, column, row}; pyramid.contains(child)) out.push_back(child);
}

void selectLayer(const SelectableLayer& layer, int number, const Viewing& viewing, std::vector<WantedPage>& wanted) {
  const PagePyramid& pyramid = *layer.pyramid;
  std::vector<PageKey> level;
  const int top = pyramid.levels() - 1;
  for (int row = 0; row < pyramid.pagesDown(top); ++row)
    for (int column = 0; column < pyramid.pagesAcross(top); ++column) level.push_back({top, column, row});
  for (int depth = 0; !level.empty() && wanted.size() < kMostWanted; ++depth) {
    std::vector<PageKey> finer;
    for (const PageKey& key : level) {
      const PageBounds bounds = boundsOf(layer, key, viewing);
      if (!bounds.visible) continue;
      wanted.push_back({{number, key}, depth, bounds.distance});
      if (bounds.refine) addChildren(pyramid, key, finer);
    }
    level = std::move(finer);
  }
}

}  // namespace

std::vector<WantedPage> selectPages(const std::vector<SelectableLayer>& layers, const Body& body, const View& view,
                                    const HeightRange& terrain) {
  const Viewing viewing = viewingOf(body, view, terrain);
  std::vector<WantedPage> wanted;
  for (std::size_t i = 0; i < layers.size(); ++i) selectLayer(layers[i], int(i), viewing, wanted);
  std::ranges::sort(wanted, [](const WantedPage& a, const WantedPage& b) {
    return a.depth != b.depth ? a.depth < b.depth : a.distance < b.distance;
  });
  return wanted;
}

}  // namespace strata::paging
