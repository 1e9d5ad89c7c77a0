#include "zoom_pan_curve.hpp"

#include <cmath>

namespace strata::paths {
namespace {

// Below this ground distance (in the curve's unit, metres for flights) the path is the pure zoom their
// general solution tends to as u1 -> 0, which it cannot compute (it divides by u1).
constexpr double kSameGround = 1e-6;

}  // namespace

ZoomPanCurve::ZoomPanCurve(double u1, double w0, double w1, double rho)
    : w0_(w0), w1_(w1), rho_(rho), pans_(u1 >= kSameGround) {
  if (!pans_) {
    length_ = std::abs(std::log(w1 / w0)) / rho;
    return;
  }
  const double rho2 = rho * rho, rho4 = rho2 * rho2;
  const double b0 = (w1 * w1 - w0 * w0 + rho4 * u1 * u1) / (2.0 * w0 * rho2 * u1);
  const double b1 = (w1 * w1 - w0 * w0 - rho4 * u1 * u1) / (2.0 * w1 * rho2 * u1);
  // r = ln(-b + sqrt(b^2 + 1)) = -asinh(b), without the first form's cancellation for large b.
  r0_ = -std::asinh(b0);
  length_ = (-std::asinh(b1) - r0_) / rho;
}

double ZoomPanCurve::ground(double s) const {
  if (!pans_) return 0.0;
  return w0_ / (rho_ * rho_) * (std::cosh(r0_) * std::tanh(rho_ * s + r0_) - std::sinh(r0_));
}

double ZoomPanCurve::width(double s) const {
  if (!pans_) return w0_ * std::exp((w1_ < w0_ ? -1.0 : 1.0) * rho_ * s);
  return w0_ * std::cosh(r0_) / std::cosh(rho_ * s + r0_);
}

}  // namespace strata::paths
