#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace strata::clipmap {

// The static hemisphere of spherical clipmaps [Clasen & Hege 2006, §3.4], built once and uploaded
// once: concentric rings about the point below the viewer, whose colatitude from it (theta~) halves level by level
// toward it, every ring cut into the same `steps` (the paper's n) around, so that no T-junction and no crack lies
// between levels. Level i spans theta~ from pi 2^-i in to pi 2^-(i+1) in `ringsPerLevel` rings (the paper's m):
// ring r of the mesh lies at theta~ = pi 2^(-r/m), so that triangles twice as far are twice as large and about
// as large on screen. Inside the finest level a view draws, its fill cap: a fan from the point below the viewer.
//
// A vertex is a unit vector in the viewer's east-north-up frame (strata/camera.hpp's planetToLocal at
// View::reference): phi~ counts clockwise from north, so that the mesh's seams beyond the poles lie along two
// fixed columns [Clasen & Hege 2006, §4.4]: the one due north (beyond the north pole) and the one due south.
// Each column of those two is held twice, once for the eastern half's triangles and once for the western's, and
// each vertex says its half, so that the vertex shader unwraps its longitude into it.
//
// Each level's triangles lie sector by sector (`sectors` equal wedges of phi~, each within one half), so that a
// view draws only the sectors its frustum may hold (sector_culling.hpp): the paper's first proposal for future
// work, "view-frustum culling" [Clasen & Hege 2006, §6.1].
struct RingSettings {
  int steps = 512;         // around each ring (n), even: the paper's 512
  int ringsPerLevel = 20;  // m: the paper's 20, triangles about 2.8 times as long radially as across
  int levels = 40;         // in the mesh: the finest ring lies pi 2^-40 from the viewer's nadir, 18 um on Earth
};

struct HemisphereVertex {
  float east, north;  // the unit vector's horizontal components
  float upMinusOne;   // its vertical component less 1, -2 sin^2(theta~ / 2): float keeps it near the nadir
  float colatitude;   // theta~, rad, negative on the western half (phi~ in [pi, 2 pi]); 0 at the nadir
};

struct IndexRange {
  std::uint32_t first = 0, count = 0;  // indices
};

struct HemisphereRings {
  RingSettings settings;
  int sectors = 2;  // wedges of phi~ a level: up to 16, each an equal share of one half's columns
  std::vector<HemisphereVertex> vertices;
  std::vector<std::uint32_t> indices;  // triangles
  std::vector<IndexRange> levels;      // level i's triangles, 2 steps ringsPerLevel of them, sector by sector
  std::vector<IndexRange> caps;        // the fill cap inside level i: `steps` triangles
};

// The unit vector at theta~ `colatitude` and phi~ `azimuth` (rad, clockwise from north) in the east-north-up frame of
// the point below the viewer.
glm::dvec3 hemisphereDirection(double colatitude, double azimuth);

// theta~ of ring `ring` (0: the antipode), rad.
double ringColatitude(int ring, int ringsPerLevel);

// The mesh of `settings`; steps even and at least 4, ringsPerLevel and levels at least 1.
HemisphereRings buildHemisphereRings(const RingSettings& settings);

// The triangles of sector `sector` of level `level`.
IndexRange sectorRange(const HemisphereRings& mesh, int level, int sector);
// Where sector `sector`'s wedge begins: phi~, rad clockwise from north; it ends where the next begins.
double sectorAzimuth(const HemisphereRings& mesh, int sector);

}  // namespace strata::clipmap
