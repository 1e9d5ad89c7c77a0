#pragma once
#include <vector>

// A C1 cubic through samples of one quantity (log altitude, heading, tilt, field of view) that never
// overshoots them: between two samples it stays between their values, so an altitude never dips below the
// lowest keyframe nor a tilt past 90 degrees. Fritsch and Carlson 1980, "Monotone piecewise cubic
// interpolation", with the tangents of Fritsch and Butland 1984 (MATLAB's pchip).
namespace strata::paths {

class MonotoneCubic {
 public:
  // Samples at strictly increasing times; the slope is 0 at the first and last, where a path starts and
  // ends at rest.
  MonotoneCubic(std::vector<double> times, std::vector<double> values);

  // The value at `time` within segment `segment` (times[segment] <= time <= times[segment + 1]).
  double at(std::size_t segment, double time) const;

 private:
  std::vector<double> times_;
  std::vector<double> values_;
  std::vector<double> slopes_;
};

// The cubic Hermite basis: the value at u in [0, 1] of the cubic from y0 with slope m0 (per unit u) to y1
// with slope m1.
double hermite(double y0, double m0, double y1, double m1, double u);

}  // namespace strata::paths
