#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

namespace strata::clipmap {

// The window of one level's height clipmap [Clasen & Hege 2006, §3.1, §4.1]: `texels` x `texels` texels of
// longitude and latitude about the point below the eye, which hold every point within the level's theta~
// (pi 2^-level) of it with a texel to spare for bilinear filtering.
// - Latitude: the level's 2 theta~ across `texels` - 4 texels, one fixed size a level.
// - Longitude: the cap's extent there (§4.1 as docs/references.md corrects it: asin(sin theta~ / cos latitude)
//   either way) in a texel that is the latitude's times a power of 2^(1/4), so that moving north or south changes
//   it only in steps, and the window's texels stay where they are in between (§4.1 steps by powers of two, which
//   double the texel just off the equator). Where the cap holds a pole, or the texel would span more than a turn,
//   the window spans the whole turn.
// Texel (i, j) of the body's lattice for a window's texel sizes covers longitude [i, i + 1) texels east of the
// prime meridian and latitude [j, j + 1) texels north of the south pole. A window's texel k (0 to texels - 1
// each way) is lattice texel origin + k, kept in its texture at (origin + k) mod texels: moving the window
// re-samples only the texels it moves in (toroidal updates, §3.1).
struct HeightWindow {
  glm::dvec2 texel{0.0};   // rad of longitude and latitude
  glm::i64vec2 origin{0};  // the lattice texel of the window's texel (0, 0)
  bool wholeTurn = false;  // spans every longitude; origin.x is 0
  bool operator==(const HeightWindow&) const = default;
};

// Texels across a level's window for rings of `steps` (the paper's n): n / 2, at most 512. The paper finds n / 4
// enough [Clasen & Hege 2006, §4.2], counting the texels a level's square window has along its rim, but a ring's
// vertices lie pi theta~ / n apart around it at a level's inner edge, where n / 4 texels put a texel 2.5 of them
// across: a quarter-metre DEM seen at 45 degrees from 10 m came out 3.3 cm off where n / 2 keeps it within 1 cm,
// and a cut's step in the heights moved by a texel showed. At the default 512 steps, 256 texels: 0.5 MB a level.
int clipmapTexels(int steps);

// The window of level `level` about `reference` (rad: longitude, latitude), `texels` across (at least 8).
HeightWindow heightWindow(int level, glm::dvec2 reference, int texels);

// Where a window's texel k lies in its texture: (origin + k) mod texels, taken as the offset added to k.
glm::ivec2 textureOffset(const HeightWindow& window, int texels);

// Longitude and latitude of the window's lattice corner (texel (0, 0)'s south-west corner) from `reference`, rad,
// worked out in double: what the GPU adds its small offsets to.
glm::dvec2 cornerFromReference(const HeightWindow& window, glm::dvec2 reference);

// A block of a window's texels: k from `first` to first + count - 1.
struct TexelBlock {
  glm::ivec2 first{0}, count{0};
  bool operator==(const TexelBlock&) const = default;
};

// The texels of `wanted` to sample, where the texture holds `held` (none: nothing yet, or what it held is stale):
// every texel where the texel sizes differ or the window moved by a whole width, else the columns and rows it
// moved in (at most two blocks; the corner they share lies in both).
std::vector<TexelBlock> texelsToSample(const std::optional<HeightWindow>& held, const HeightWindow& wanted, int texels);

}  // namespace strata::clipmap
