#include "monotone_cubic.hpp"

#include <utility>

namespace strata::paths {
namespace {

// Fritsch and Butland's weighted harmonic mean of the secants on either side of a sample, or 0 at a local
// extremum or plateau, so that no segment overshoots its ends.
double interiorSlope(double hBefore, double secantBefore, double hAfter, double secantAfter) {
  if (secantBefore * secantAfter <= 0.0) return 0.0;
  const double w1 = 2.0 * hAfter + hBefore;
  const double w2 = hAfter + 2.0 * hBefore;
  return (w1 + w2) / (w1 / secantBefore + w2 / secantAfter);
}

}  // namespace

double hermite(double y0, double m0, double y1, double m1, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return (2.0 * u3 - 3.0 * u2 + 1.0) * y0 + (u3 - 2.0 * u2 + u) * m0 + (-2.0 * u3 + 3.0 * u2) * y1 + (u3 - u2) * m1;
}

MonotoneCubic::MonotoneCubic(std::vector<double> times, std::vector<double> values)
    : times_(std::move(times)), values_(std::move(values)), slopes_(times_.size(), 0.0) {
  for (std::size_t k = 1; k + 1 < times_.size(); ++k) {
    const double hBefore = times_[k] - times_[k - 1], hAfter = times_[k + 1] - times_[k];
    slopes_[k] =
        interiorSlope(hBefore, (values_[k] - values_[k - 1]) / hBefore, hAfter, (values_[k + 1] - values_[k]) / hAfter);
  }
}

double MonotoneCubic::at(std::size_t segment, double time) const {
  const double h = times_[segment + 1] - times_[segment];
  const double u = (time - times_[segment]) / h;
  return hermite(values_[segment], slopes_[segment] * h, values_[segment + 1], slopes_[segment + 1] * h, u);
}

}  // namespace strata::paths
