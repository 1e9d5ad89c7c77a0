#pragma once
#include <functional>
#include <vector>

#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/plugin/spherical_cap.hpp>

#include "drawn_levels.hpp"
#include "hemisphere_rings.hpp"

namespace strata::clipmap {

// The triangles a view draws: each sector of the drawn levels that the view's frustum may hold, and the fill cap
// ([Clasen & Hege 2006, §6.1]'s "view-frustum culling", computed on the CPU in double). A sector is left out only
// where every point of its shell (its wedge of the rings between the spheres of the lowest and the highest ground
// over it: `heightsOver` a cap holding the wedge and the footprints of its heights) lies outside one side of the
// frustum, widened by `marginPixels`. Adjacent ranges are merged, so that a view seen whole is one range and its
// cap. Where the eye lies within a wedge's heights, its shell holds points on every side of the eye, and it is
// drawn: regional heights (HeightInput::within) keep that to the wedges about the eye.
using HeightsOver = std::function<HeightRange(const SphericalCap& cap)>;
std::vector<IndexRange> visibleRanges(const HemisphereRings& mesh, const DrawnLevels& drawn, const View& view,
                                      double radius, const HeightsOver& heightsOver, double marginPixels = 2.0);

}  // namespace strata::clipmap
