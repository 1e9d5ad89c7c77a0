#pragma once
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>
#include <strata/camera.hpp>

namespace strata::icosahedral {

// The fly-in of [Kooima 2008, §5.1] over a Mars-sized body, as strata-bench-flyin flies it and the patch
// tree's tests follow it: from 10,000 km down to 300 m above a summit and back, at 30 Hz. The altitude
// falls geometrically, starting 2 km south of the summit and looking north, tilting from straight down to
// 75 degrees below 100 km.
struct FlyInPath {
  static constexpr double kMarsRadius = 3396190.0;                       // m
  static constexpr int kFramesEachWay = 150;                             // 5 s down and 5 s up at 30 Hz
  static constexpr double kStartAltitude = 1.0e7, kAboveSummit = 300.0;  // m

  double summitLon = 0.0, summitLat = 0.0;  // deg
  double summitHeight = 0.0;                // m

  // The camera of frame `frame`, 0 to 2 * kFramesEachWay - 1.
  Camera cameraAt(int frame) const {
    const int step = frame < kFramesEachWay ? frame : 2 * kFramesEachWay - 1 - frame;
    const double t = double(step) / double(kFramesEachWay - 1);
    const double low = summitHeight + kAboveSummit;
    const double altitude = kStartAltitude * std::pow(low / kStartAltitude, t);
    const double closeness = std::clamp(std::log10(1.0e5 / altitude) / std::log10(1.0e5 / low), 0.0, 1.0);
    return {.lon = summitLon,
            .lat = summitLat - glm::degrees(2000.0 / kMarsRadius) * closeness,
            .altitude = altitude,
            .heading = 0.0,
            .tilt = 75.0 * closeness,
            .fov = 45.0};
  }
};

}  // namespace strata::icosahedral
