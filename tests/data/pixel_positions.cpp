#include "pixel_positions.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace strata::testdata {

PixelPositions::PixelPositions(const Observation& observation)
    : observation_(observation),
      context_(proj_context_create()),
      projection_(proj_create(context_, observation.crs.c_str())),
      x_(std::size_t(observation.width)),
      y_(std::size_t(observation.width)),
      lonlat_(std::size_t(observation.width)) {
  if (!projection_) {
    const std::string reason = proj_context_errno_string(context_, proj_context_errno(context_));
    proj_context_destroy(context_);
    throw std::runtime_error("PROJ cannot make '" + observation.crs + "': " + reason);
  }
  angularMapUnits_ = proj_angular_input(projection_, PJ_INV);
}

PixelPositions::~PixelPositions() {
  proj_destroy(projection_);
  proj_context_destroy(context_);
}

const std::vector<glm::dvec2>& PixelPositions::row(int row) {
  const double toRadians = angularMapUnits_ ? std::acos(-1.0) / 180.0 : 1.0;
  const double y = (observation_.north - (row + 0.5) * observation_.pixelHeight) * toRadians;
  for (std::size_t i = 0; i < x_.size(); ++i) {
    x_[i] = (observation_.west + (double(i) + 0.5) * observation_.pixelWidth) * toRadians;
    y_[i] = y;
  }
  // Points PROJ cannot invert (HEALPix's empty corners) come back as HUGE_VAL.
  proj_trans_generic(projection_, PJ_INV, x_.data(), sizeof(double), x_.size(), y_.data(), sizeof(double), y_.size(),
                     nullptr, 0, 0, nullptr, 0, 0);
  proj_errno_reset(projection_);
  for (std::size_t i = 0; i < x_.size(); ++i) {
    const bool inverted = std::isfinite(x_[i]) && std::isfinite(y_[i]);
    lonlat_[i] = inverted ? glm::dvec2(x_[i], y_[i]) : glm::dvec2(std::numeric_limits<double>::quiet_NaN());
  }
  return lonlat_;
}

}  // namespace strata::testdata
