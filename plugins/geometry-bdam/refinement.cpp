#include "refinement.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "diamonds.hpp"

namespace strata::bdam {
namespace {

bool outsideFrustum(const View& view, const BoundingSphere& sphere) {
  const glm::dvec3 c = view.toEye(sphere.centre);
  const glm::dvec2 tangents = view.halfFrameTangents();
  if (c.z - sphere.radius > -view.near) return true;        // wholly before the near plane
  const auto beyond = [&](double across, double tangent) {  // (|across| + z tangent) / sqrt(1 + tangent^2) > r
    return (std::abs(across) + c.z * tangent) / std::sqrt(1.0 + tangent * tangent) > sphere.radius;
  };
  return beyond(c.x, tangents.x) || beyond(c.y, tangents.y);
}

bool behindTheBody(const View& view, const BoundingSphere& sphere, double lowestRadius) {
  const double eye = glm::length(view.eye), centre = glm::length(sphere.centre);
  if (eye <= lowestRadius || centre <= sphere.radius) return false;
  const double angle = std::acos(std::clamp(glm::dot(view.eye, sphere.centre) / (eye * centre), -1.0, 1.0));
  const double spread = std::asin(sphere.radius / centre);
  const double reach =
      std::acos(lowestRadius / eye) + std::acos(std::min(1.0, lowestRadius / (centre + sphere.radius)));
  return angle - spread > reach;
}

// The node's error in pixels seen from the eye at the nearest point of its sphere.
double pixelsOf(const View& view, const NodeRecord& record) {
  const double distance = glm::length(record.sphere.centre - view.eye) - record.sphere.radius;
  return record.error * view.pixelsPerRadian() / std::max(distance, view.near);
}

}  // namespace

bool culled(const View& view, const BoundingSphere& sphere, double lowestRadius) {
  return outsideFrustum(view, sphere) || behindTheBody(view, sphere, lowestRadius);
}

Cut refine(const View& view, int leafLevel, double pixelError, double lowestRadius, const NodeLookup& nodes) {
  Cut cut;
  std::vector<BintreeNode> level;
  for (int root = 0; root < kBintreeRoots; ++root) level.push_back({root, 0, 0});
  while (!level.empty()) {
    std::map<HypotenuseKey, std::vector<BintreeNode>> diamonds;
    for (const BintreeNode& node : level) diamonds[hypotenuseOf(node)].push_back(node);
    std::vector<BintreeNode> finer;
    for (const auto& [key, halves] : diamonds) {
      cut.visited += halves.size();
      const std::optional<NodeRecord> record = nodes.record(halves.front());
      if (!record) continue;
      const bool wanted = halves.front().level < leafLevel && pixelsOf(view, *record) > pixelError;
      const bool hidden = culled(view, record->sphere, lowestRadius);
      bool ready = wanted && halves.size() == 2;
      if (ready && !hidden)
        for (const BintreeNode& half : halves)
          for (const BintreeNode& child : children(half))
            if (!nodes.resident(child)) {
              cut.missing.push_back(child);
              ready = false;
            }
      for (const BintreeNode& half : halves)
        if (ready) {
          const auto pair = children(half);
          finer.insert(finer.end(), pair.begin(), pair.end());
        } else if (!hidden) {
          (nodes.resident(half) ? cut.drawn : cut.missing).push_back(half);  // only a root can be missing here
        }
    }
    level.swap(finer);
  }
  return cut;
}

}  // namespace strata::bdam
