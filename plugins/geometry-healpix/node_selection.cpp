#include "node_selection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <unordered_map>
#include <utility>

#include <glm/geometric.hpp>
#include <strata/plugin/geometric_error.hpp>

namespace strata::healpix {
namespace {

// The angle at the centre between the eye's direction and a tangent ray from an eye at distance d to the
// sphere of radius r <= d, acos(r / d), in a form that keeps its digits near 0 (2 m over Earth).
double tangentAngle(double r, double d) { return std::atan2(std::sqrt((d - r) * (d + r)), r); }

// The largest of dot(n, u) over the unit vectors u of the cone: the cosine of n's angle to the nearest of them.
double largestDot(const NodeCone& cone, const glm::dvec3& n) {
  return std::cos(std::max(0.0, angleBetween(cone.centre, n) - cone.angle));
}

// The convex hull of points in the plane, counter-clockwise (Andrew's monotone chain).
std::vector<glm::dvec2> convexHull(std::array<glm::dvec2, 8> points) {
  std::ranges::sort(points,
                    [](const glm::dvec2& a, const glm::dvec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const auto turn = [](const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  };
  std::vector<glm::dvec2> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t start = hull.size();
    for (const glm::dvec2& p : points) {
      while (hull.size() >= start + 2 && turn(hull[hull.size() - 2], hull.back(), p) <= 0.0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();  // each chain's last point starts the other
    std::ranges::reverse(points);
  }
  return hull;
}

// The part of a convex polygon inside the rectangle |x| <= half.x, |y| <= half.y (Sutherland-Hodgman).
std::vector<glm::dvec2> clipToRectangle(std::vector<glm::dvec2> polygon, const glm::dvec2& half) {
  for (int side = 0; side < 4 && !polygon.empty(); ++side) {
    const int axis = side / 2;
    const double sign = side % 2 == 0 ? 1.0 : -1.0;
    const auto inside = [&](const glm::dvec2& p) { return sign * p[axis] <= half[axis]; };
    std::vector<glm::dvec2> clipped;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const glm::dvec2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
      if (inside(a)) clipped.push_back(a);
      if (inside(a) != inside(b)) {
        const double t = (sign * half[axis] - a[axis]) / (b[axis] - a[axis]);
        clipped.push_back(a + t * (b - a));
      }
    }
    polygon = std::move(clipped);
  }
  return polygon;
}

double polygonArea(const std::vector<glm::dvec2>& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2 &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

}  // namespace

ShellView::ShellView(const View& view, double radius, HeightRange heights, NodeHeights nodeHeights)
    : eye_(view.eye),
      planetToEye_(view.planetToEye),
      near_(view.near),
      focal_(view.pixelsPerRadian()),
      halfScreen_(0.5 * double(view.width), 0.5 * double(view.height)),
      pixelsPerSteradian_(focal_ * focal_ *
                          std::pow(1.0 + glm::dot(halfScreen_, halfScreen_) / (focal_ * focal_), 1.5)),
      radius_(radius),
      heights_(heights),
      nodeHeights_(std::move(nodeHeights)) {
  const glm::dvec2 halfFrame = view.halfFrameTangents();
  const double tx = halfFrame.x, ty = halfFrame.y;
  // Eye space looks down -z: a point is inside when |x| <= tx (-z), |y| <= ty (-z) and -z >= near.
  const std::array<glm::dvec3, 5> eyeNormals{glm::dvec3(1, 0, -tx), glm::dvec3(-1, 0, -tx), glm::dvec3(0, 1, -ty),
                                             glm::dvec3(0, -1, -ty), glm::dvec3(0, 0, -1)};
  const glm::dmat3 eyeToPlanet = glm::transpose(planetToEye_);
  for (std::size_t i = 0; i < planes_.size(); ++i) {
    const double length = glm::length(eyeNormals[i]);
    planes_[i] = {eyeToPlanet * eyeNormals[i] / length, i == 4 ? -near_ : 0.0};
  }
}

NodeShell ShellView::shellOf(const NodeKey& key) const {
  NodeShell shell;
  const std::array<glm::dvec3, 8> boundary = boundarySamples(key);
  shell.cone = coneAround(unitVector(key.centre()), boundary);
  const std::optional<RegionalHeights> known = nodeHeights_ ? nodeHeights_(key, shell.cone) : std::nullopt;
  const HeightRange heights = known ? known->range : heights_;
  if (known) shell.finest = known->finest;
  const double innerRadius = radius_ + heights.lowest, outerRadius = radius_ + heights.highest;
  shell.innerRadius = innerRadius;
  shell.outerRadius = outerRadius;
  const glm::dvec3& n = shell.cone.centre;
  // Tangent axes along the node's x direction (south and west corners to east and north), so that the box
  // fits the node's sides rather than its diagonals.
  const glm::dvec3 along = boundary[2] - boundary[0] + boundary[4] - boundary[6];
  const glm::dvec3 t1 = glm::normalize(along - glm::dot(along, n) * n), t2 = glm::cross(n, t1);
  // Extents over the samples at both radii, widened by the cone's margin for the edges' bulge between them
  // and clipped to the cone, which holds the node with that margin.
  const double angle = std::min(shell.cone.angle, 0.5 * std::numbers::pi);
  const double sampledSine = std::sin(angle / kConeMargin), coneSine = std::sin(angle);
  const double widen = (kConeMargin - 1.0) * sampledSine * outerRadius, clip = coneSine * outerRadius;
  glm::dvec2 low(std::numeric_limits<double>::max()), high(std::numeric_limits<double>::lowest());
  for (const glm::dvec3& u : boundary) {
    for (const double r : {innerRadius, outerRadius}) {
      const glm::dvec2 t(r * glm::dot(u, t1), r * glm::dot(u, t2));
      low = glm::min(low, t);
      high = glm::max(high, t);
    }
  }
  low = glm::max(low - widen, glm::dvec2(-clip));
  high = glm::min(high + widen, glm::dvec2(clip));
  const double cosine = std::cos(angle);
  const std::array<double, 2> depths{std::min(innerRadius * cosine, outerRadius * cosine), outerRadius};
  for (std::size_t i = 0; i < 8; ++i) {
    const double a = depths[i & 1], u = (i & 2) ? high.x : low.x, v = (i & 4) ? high.y : low.y;
    shell.box[i] = a * n + u * t1 + v * t2;
  }
  return shell;
}

bool ShellView::culled(const NodeShell& shell) const {
  for (const Plane& plane : planes_) {
    const double m = largestDot(shell.cone, plane.normal);
    const double farthest = (m >= 0.0 ? shell.outerRadius : shell.innerRadius) * m;
    // A micrometre of slack for the rounding of dot(normal, eye) at planet scale (1e-9 m).
    if (farthest - glm::dot(plane.normal, eye_) + plane.offset < -1e-6) return true;
  }
  // The body hides what lies behind it down to its lowest height anywhere, not the node's.
  const double distance = glm::length(eye_), lowest = radius_ + heights_.lowest;
  if (distance <= lowest) return false;
  const double horizon = tangentAngle(lowest, distance) + tangentAngle(lowest, std::max(shell.outerRadius, lowest));
  return angleBetween(shell.cone.centre, eye_ / distance) - shell.cone.angle > horizon;
}

double ShellView::boxArea(const NodeShell& shell) const {
  std::array<glm::dvec2, 8> screen;
  for (std::size_t i = 0; i < 8; ++i) {
    const glm::dvec3 q = planetToEye_ * (shell.box[i] - eye_);
    const double depth = -q.z;
    if (depth <= near_) return std::numeric_limits<double>::infinity();
    screen[i] = glm::dvec2(q.x, q.y) * (focal_ / depth);
  }
  return polygonArea(clipToRectangle(convexHull(screen), halfScreen_));
}

// The nearest point of the cone's shell: at the cone's nearest direction, at the radius nearest the eye; its
// squared distance as (d - r)^2 + 4 d r sin^2(psi / 2), which keeps its digits 1 m above the ground.
double ShellView::nearestDistanceSquared(const NodeShell& shell) const {
  const double d = glm::length(eye_);
  const double psi = std::max(0.0, angleBetween(shell.cone.centre, eye_ / d) - shell.cone.angle);
  const double r = std::clamp(d * std::cos(psi), shell.innerRadius, shell.outerRadius), s = std::sin(0.5 * psi);
  return (d - r) * (d - r) + 4.0 * d * r * s * s;
}

double ShellView::faceOnArea(const NodeShell& shell, const NodeKey& key) const {
  const double area = std::numbers::pi * shell.outerRadius * shell.outerRadius / (3.0 * std::ldexp(1.0, 2 * key.level));
  return kSlopeAllowance * area * pixelsPerSteradian_ / nearestDistanceSquared(shell);
}

// A node is about sqrt(pi / 3) rad across at level 0 (HEALPix is equal area), halved each level.
double ShellView::screenError(const NodeShell& shell, const NodeKey& key, int gridCells) const {
  const double spacing = std::ldexp(std::sqrt(std::numbers::pi / 3.0), -key.level) / gridCells;
  const double fromPole = std::acos(std::min(std::abs(shell.cone.centre.z), 1.0)) - shell.cone.angle;
  const double sphere = chordError(radius_, spacing, fromPole);
  const double width = 2.0 * shell.cone.angle;
  const double terrain =
      reliefWithinSpacing(shell.outerRadius - shell.innerRadius, shell.finest, width, width / gridCells);
  return std::max(sphere, terrain) * std::sqrt(pixelsPerSteradian_ / nearestDistanceSquared(shell));
}

double ShellView::projectedArea(const NodeShell& shell, const NodeKey& key) const {
  return std::min(boxArea(shell), faceOnArea(shell, key));
}

namespace {

// The quadtrees one selection visits: every node it reached, as refined (inner), drawn or culled. The
// terminal nodes tile every face, so a point's node is found by descending from its face.
class VisitedTree {
 public:
  enum class State { inner, drawn, culled };

  VisitedTree(const ShellView& shells, const SelectionSettings& settings) : shells_(shells), settings_(settings) {}

  // [Westerteiger et al. 2011, §3.2], without the paper's loading: cull, draw when adequate, else refine.
  void traverse(const NodeKey& key) {
    const NodeShell shell = shells_.shellOf(key);
    if (shells_.culled(shell)) {
      states_[key] = State::culled;
      return;
    }
    const bool adequate = shells_.projectedArea(shell, key) * settings_.threshold <= settings_.gridVertices() ||
                          shells_.screenError(shell, key, settings_.gridCells) <= settings_.pixelError;
    if (adequate || key.level >= settings_.maxLevel) {
      states_[key] = State::drawn;
      drawn_.push_back(key);
      return;
    }
    states_[key] = State::inner;
    for (const NodeKey& child : key.children()) traverse(child);
  }

  // The terminal node holding a point, if it lies at `deepest` or above.
  std::optional<std::pair<NodeKey, State>> terminalAt(const FacePoint& point, int deepest) const {
    for (int level = 0; level <= deepest; ++level) {
      const NodeKey key = nodeAt(point, level);
      const auto found = states_.find(key);
      if (found == states_.end()) return std::nullopt;
      if (found->second != State::inner) return std::pair{key, found->second};
    }
    return std::nullopt;
  }

  // Splits drawn nodes two or more levels coarser than a drawn neighbour until none is
  // ([Westerteiger et al. 2011] leaves these cracks open; docs/healpix.md, "Selection"). Each drawn node
  // looks across its edges for coarser ones; a split's drawn children look in turn, so the splits ripple
  // outward as far as they must.
  void balance() {
    std::vector<NodeKey> pending = drawn_;
    while (!pending.empty()) {
      const NodeKey key = pending.back();
      pending.pop_back();
      if (states_[key] != State::drawn) continue;
      for (int edge = 0; edge < 4; ++edge) {
        const FacePoint beyond = acrossEdge(key, edge);
        while (const auto coarse = terminalAt(beyond, key.level - 2)) {
          if (coarse->second != State::drawn) break;
          split(coarse->first, pending);
        }
      }
    }
  }

  // The drawn nodes, depth first, each with its coarser edges.
  std::vector<SelectedNode> selected() const {
    std::vector<SelectedNode> nodes;
    for (int face = 0; face < 12; ++face) collect(NodeKey{face, 0, 0, 0}, nodes);
    return nodes;
  }

 private:
  void split(const NodeKey& key, std::vector<NodeKey>& pending) {
    states_[key] = State::inner;
    for (const NodeKey& child : key.children()) {
      const bool visible = !shells_.culled(shells_.shellOf(child));
      states_[child] = visible ? State::drawn : State::culled;
      if (visible) pending.push_back(child);
    }
  }

  unsigned coarserEdges(const NodeKey& key) const {
    unsigned edges = 0;
    for (int edge = 0; edge < 4 && key.level > 0; ++edge) {
      const auto across = terminalAt(acrossEdge(key, edge), key.level - 1);
      if (across && across->second == State::drawn) edges |= 1u << edge;
    }
    return edges;
  }

  void collect(const NodeKey& key, std::vector<SelectedNode>& nodes) const {
    const State state = states_.at(key);
    if (state == State::drawn) nodes.push_back({key, coarserEdges(key)});
    if (state != State::inner) return;
    for (const NodeKey& child : key.children()) collect(child, nodes);
  }

  const ShellView& shells_;
  const SelectionSettings& settings_;
  std::unordered_map<NodeKey, State, NodeKeyHash> states_;
  std::vector<NodeKey> drawn_;
};

}  // namespace

std::vector<SelectedNode> selectNodes(const View& view, double radius, HeightRange heights,
                                      const SelectionSettings& settings, const NodeHeights& nodeHeights) {
  const ShellView shells(view, radius, heights, nodeHeights);
  VisitedTree tree(shells, settings);
  for (int face = 0; face < 12; ++face) tree.traverse(NodeKey{face, 0, 0, 0});
  tree.balance();
  return tree.selected();
}

}  // namespace strata::healpix
