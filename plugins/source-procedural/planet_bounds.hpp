#pragma once
// Bounds of the procedural planet's heights over a cap of the sphere, so that geometry measures a patch on
// the terrain it holds rather than on the planet's whole range (RegionalValueLayer::valuesWithin; docs/geometry.md,
// "Height ranges"). In double on the CPU, from the noise at the cap's centre and the noise's slope bound.
#include <glm/glm.hpp>

#include "planet_model.hpp"

namespace strata::procedural {

struct HeightBounds {
  double least = 0.0;     // m
  double greatest = 0.0;  // m
};

// The heights (m, before any scale) that samples within `angle` rad of unit vector `centre` can return,
// filtered as the GPU filters them for footprints up to the cap's diameter (every octave up to one that a
// footprint of that size fades: octaveWeight). Samples of wider footprints fade more of the finer octaves
// and may fall outside by as much as those octaves reach; generators widen their caps by a few of their
// samples' footprints, which keeps them well within.
HeightBounds heightsWithin(const PlanetModel& planet, const glm::dvec3& centre, double angle);

}  // namespace strata::procedural
