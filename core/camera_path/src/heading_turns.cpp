#include <cmath>

#include "camera_motion.hpp"

namespace strata::paths {

double nearestHeading(double from, double to) {
  double turn = std::fmod(to - from, 360.0);
  if (turn > 180.0) turn -= 360.0;
  if (turn <= -180.0) turn += 360.0;
  return from + turn;
}

double wrapHeading(double heading) {
  double wrapped = std::fmod(heading, 360.0);
  if (wrapped < 0.0) wrapped += 360.0;
  return wrapped == 360.0 ? 0.0 : wrapped;  // -1e-17 + 360 rounds up to 360
}

}  // namespace strata::paths
