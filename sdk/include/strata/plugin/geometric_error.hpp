#pragma once
// The geometric error a generator's grid of vertices makes, m: what its level of detail by screen-space error
// bounds on screen (docs/geometry.md, "Level of detail by screen-space error"). geometry.icosahedral and
// geometry.healpix measure theirs alike.
#include <optional>
#include <strata/export.hpp>

#include <strata/plugin/layer.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// The sphere's: a chord of `spacing` rad misses a sphere of `radius` m by its sagitta R a^2 / 8, and so do the
// longitude and latitude interpolated along it, except that longitude bends along a chord as the cotangent of its
// distance θ from the pole, `fromPole` rad (floored at one spacing, where the pole itself is a vertex).
double chordError(double radius, double spacing, double fromPole);
// The sagitta alone, R a^2 / 8: the part of chordError that is radial, which shows in full where the ground is
// seen edge on; the longitude's bending lies along the ground.
double chordSagitta(double radius, double spacing);

// The relief, m, that a grid of vertex spacing `spacing` may hide in a region `width` wide (both rad, the width
// measured as BlockRelief's: a cap's diameter) whose relief is `relief`: an estimate, since the heights between
// two vertices are unknown. The lesser of two bounds. First order: the relief scaled down to the spacing as
// relief ∝ size^H, the roughness H measured between the region and the layer's finest blocks within it, clamped
// to [0.5, 1]: 1 where the relief is a slope or a swell, which shrinks as the size does; 0.5 for relief as rough
// as Brownian (height differences growing as the square root of distance), taken also where no finer blocks are
// known or the region is no wider than one, so that the estimate errs toward detail. Second order, where the
// blocks know their curvature c: linear interpolation between vertices s apart misses a surface of curvature
// at most c by at most c s^2 / 4 (a triangle's circumradius r misses by c r^2 / 2, and r <= s / sqrt 2 for the
// spacings generators give, a cap's diameter), s at least the data's texel, within which they are bilinear:
// smooth terrain such as a geoid, whose slopes a grid follows however large its relief, takes few vertices
// (docs/geometry.md, "Level of detail by screen-space error").
double reliefWithinSpacing(double relief, const std::optional<BlockRelief>& finest, double width, double spacing);

}  // namespace strata
STRATA_EXPORTS_END
