#pragma once
// geometry.pgm's level of detail by screen-space error (docs/pgm.md, "Level of detail"): the `grid` parameter is
// the most rays a frame casts, and a frame casts the coarsest of that grid's halvings whose error shows no more
// than the pixel error, as geometry.icosahedral and geometry.healpix refine (strata/plugin/geometric_error.hpp).
#include <glm/glm.hpp>

#include <strata/plugin/height_input.hpp>

namespace strata::pgm {

// What bounds a frame's error: the body, the eye, the view's resolution and the terrain it can see.
struct GridScene {
  double radius = 0.0;           // m: the body's
  double eyeDistance = 0.0;      // m from the body's centre
  double pixelsPerRadian = 0.0;  // the view's, at its centre
  RegionalHeights visible;       // the heights within the cap the eye can see
  double visibleWidth = 0.0;     // rad: that cap's diameter
};

// Halvings below this many cells a side are not taken: the grid must still turn with the horizon's curve.
constexpr int kFewestCells = 16;

// The most a grid whose rays lie `cell` apart (tangent units of the sampling camera's image, which bound the angle)
// may misplace the ground on screen, px: the larger of the sphere's chords between rays, whose depth below the
// sphere shows across the view, at the farthest distance the eye sees ground at (its horizon), and the relief a
// ray spacing may hide at the nearest (the eye's height above the highest terrain it sees), where a spacing's
// relief, which shrinks no faster than the spacing, shows most; both over ground seen as grazing as 83 degrees.
double gridError(const GridScene& scene, double cell);

// The grid a frame casts: `largest` halved k times per side ((side - 1) >> k cells), the largest k whose
// gridError over the sampling camera's `extent` (its image's width and height in tangent units) is at most
// `pixelError`, keeping kFewestCells; `largest` where none is, or where the pixel error is 0.
glm::ivec2 gridForError(glm::ivec2 largest, glm::dvec2 extent, const GridScene& scene, double pixelError);

}  // namespace strata::pgm
