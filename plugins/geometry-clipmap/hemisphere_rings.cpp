#include "hemisphere_rings.hpp"

#include <cmath>
#include <numbers>

namespace strata::clipmap {
namespace {

// Vertices of a ring: the eastern half's columns 0 to steps / 2, then the western half's steps / 2 to steps.
int ringVertices(const RingSettings& s) { return s.steps + 2; }

// The index of column `column` (0 to steps) of ring `ring` in the half `west`, the nadir last.
std::uint32_t vertexIndex(const RingSettings& s, int ring, int column, bool west) {
  const int half = s.steps / 2;
  return std::uint32_t(ring * ringVertices(s) + (west ? half + 1 + (column - half) : column));
}

HemisphereVertex vertexAt(double colatitude, double azimuth, bool west) {
  const glm::dvec3 d = hemisphereDirection(colatitude, azimuth);
  const double half = std::sin(0.5 * colatitude);
  return {float(d.x), float(d.y), float(-2.0 * half * half), float(west ? -colatitude : colatitude)};
}

// Two triangles a quad between rings `outer` and outer + 1, columns `column` and column + 1, within one half.
void addQuad(std::vector<std::uint32_t>& indices, const RingSettings& s, int outer, int column, bool west) {
  const std::uint32_t a = vertexIndex(s, outer, column, west), b = vertexIndex(s, outer, column + 1, west);
  const std::uint32_t c = vertexIndex(s, outer + 1, column + 1, west), d = vertexIndex(s, outer + 1, column, west);
  indices.insert(indices.end(), {a, b, c, a, c, d});
}

// Sectors a level: twice the largest power of two, up to 8, that divides a half's columns.
int sectorsOf(const RingSettings& s) {
  int perHalf = 1;
  while (perHalf < 8 && (s.steps / 2) % (2 * perHalf) == 0) perHalf *= 2;
  return 2 * perHalf;
}

}  // namespace

glm::dvec3 hemisphereDirection(double colatitude, double azimuth) {
  const double horizontal = std::sin(colatitude);
  return {horizontal * std::sin(azimuth), horizontal * std::cos(azimuth), std::cos(colatitude)};
}

double ringColatitude(int ring, int ringsPerLevel) {
  return std::numbers::pi * std::exp2(-double(ring) / double(ringsPerLevel));
}

HemisphereRings buildHemisphereRings(const RingSettings& settings) {
  const RingSettings& s = settings;
  HemisphereRings mesh{.settings = s, .sectors = sectorsOf(s)};
  const int columnsPerSector = s.steps / mesh.sectors;
  const int rings = s.levels * s.ringsPerLevel + 1, half = s.steps / 2;
  for (int ring = 0; ring < rings; ++ring) {
    const double colatitude = ringColatitude(ring, s.ringsPerLevel);
    for (int column = 0; column <= half; ++column)
      mesh.vertices.push_back(vertexAt(colatitude, 2.0 * std::numbers::pi * column / s.steps, false));
    for (int column = half; column <= s.steps; ++column)
      mesh.vertices.push_back(vertexAt(colatitude, 2.0 * std::numbers::pi * column / s.steps, true));
  }
  const auto nadir = std::uint32_t(mesh.vertices.size());
  mesh.vertices.push_back({0.0f, 0.0f, 0.0f, 0.0f});
  for (int level = 0; level < s.levels; ++level) {
    IndexRange range{std::uint32_t(mesh.indices.size()), 0};
    for (int sector = 0; sector < mesh.sectors; ++sector)
      for (int ring = level * s.ringsPerLevel; ring < (level + 1) * s.ringsPerLevel; ++ring)
        for (int column = sector * columnsPerSector; column < (sector + 1) * columnsPerSector; ++column)
          addQuad(mesh.indices, s, ring, column, column >= half);
    range.count = std::uint32_t(mesh.indices.size()) - range.first;
    mesh.levels.push_back(range);
  }
  for (int level = 0; level < s.levels; ++level) {
    IndexRange range{std::uint32_t(mesh.indices.size()), 0};
    const int inner = (level + 1) * s.ringsPerLevel;
    for (int column = 0; column < s.steps; ++column) {
      const bool west = column >= half;
      mesh.indices.insert(mesh.indices.end(),
                          {vertexIndex(s, inner, column, west), vertexIndex(s, inner, column + 1, west), nadir});
    }
    range.count = std::uint32_t(mesh.indices.size()) - range.first;
    mesh.caps.push_back(range);
  }
  return mesh;
}

IndexRange sectorRange(const HemisphereRings& mesh, int level, int sector) {
  const IndexRange& whole = mesh.levels[std::size_t(level)];
  const std::uint32_t share = whole.count / std::uint32_t(mesh.sectors);
  return {whole.first + std::uint32_t(sector) * share, share};
}

double sectorAzimuth(const HemisphereRings& mesh, int sector) { return 2.0 * std::numbers::pi * sector / mesh.sectors; }

}  // namespace strata::clipmap
