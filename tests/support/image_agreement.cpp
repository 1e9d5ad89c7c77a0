#include "image_agreement.hpp"

#include <algorithm>
#include <cstdlib>

#include "rendering.hpp"

namespace strata::test {
namespace {

// Whether every pixel within two of (x, y) is drawn in both images alike.
bool awayFromSilhouettes(const Image& a, const Image& b, int x, int y) {
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const int u = std::clamp(x + dx, 0, a.width - 1), v = std::clamp(y + dy, 0, a.height - 1);
      if (!covered(a, u, v) || !covered(b, u, v)) return false;
    }
  return true;
}

}  // namespace

ImageAgreement agreementAwayFromSilhouettes(const Image& a, const Image& b, int largeDifference) {
  ImageAgreement agreement;
  long total = 0, large = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!awayFromSilhouettes(a, b, x, y)) continue;
      ++agreement.compared;
      agreement.darkest = std::min(agreement.darkest, a.at(x, y)[1]);
      agreement.brightest = std::max(agreement.brightest, a.at(x, y)[1]);
      int worst = 0;
      for (int channel = 0; channel < 3; ++channel) {
        const int difference = std::abs(a.at(x, y)[channel] - b.at(x, y)[channel]);
        total += difference;
        worst = std::max(worst, difference);
      }
      large += worst > largeDifference;
    }
  agreement.meanDifference = double(total) / (3.0 * std::max(agreement.compared, 1));
  agreement.largeShare = double(large) / std::max(agreement.compared, 1);
  return agreement;
}

}  // namespace strata::test
