#include "image_agreement.hpp"

#include <algorithm>
#include <cstdlib>

#include "rendering.hpp"

namespace strata::test {

bool coveredAround(const Image& image, int x, int y) {
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx)
      if (!covered(image, std::clamp(x + dx, 0, image.width - 1), std::clamp(y + dy, 0, image.height - 1)))
        return false;
  return true;
}

ImageAgreement agreementAwayFromSilhouettes(const Image& a, const Image& b) {
  ImageAgreement agreement;
  long total = 0, large = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!coveredAround(a, x, y) || !coveredAround(b, x, y)) continue;
      ++agreement.compared;
      agreement.darkest = std::min(agreement.darkest, a.at(x, y)[1]);
      agreement.brightest = std::max(agreement.brightest, a.at(x, y)[1]);
      int worst = 0;
      for (int channel = 0; channel < 3; ++channel) {
        const int difference = std::abs(a.at(x, y)[channel] - b.at(x, y)[channel]);
        total += difference;
        worst = std::max(worst, difference);
      }
      large += worst > kLargeDifference;
    }
  agreement.meanDifference = double(total) / (3.0 * std::max(agreement.compared, 1));
  agreement.largeShare = double(large) / std::max(agreement.compared, 1);
  return agreement;
}

}  // namespace strata::test
