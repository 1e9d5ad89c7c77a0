#include "earth_rotation.hpp"

#include <cmath>

namespace strata {

double eclipticObliquity(double days) { return 23.439 - 0.0000004 * days; }

double greenwichSiderealAngle(double days) { return 15.0 * (18.697374558 + 24.06570982441908 * days); }

double wrapDegrees(double angle) {
  const double wrapped = std::fmod(angle + 180.0, 360.0);
  return (wrapped < 0.0 ? wrapped + 360.0 : wrapped) - 180.0;
}

}  // namespace strata
