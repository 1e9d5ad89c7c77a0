#include "proj_reference.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace strata::test {

ProjReference::ProjReference(const std::string& definition) : context_(proj_context_create()) {
  pj_ = proj_create(context_, definition.c_str());
  if (!pj_) {
    const std::string message = proj_context_errno_string(context_, proj_context_errno(context_));
    proj_context_destroy(context_);
    throw std::runtime_error("PROJ refuses '" + definition + "': " + message);
  }
  if (proj_angular_output(pj_, PJ_FWD)) outputUnitsPerRadian_ = 180.0 / std::numbers::pi;
}

ProjReference::~ProjReference() {
  proj_destroy(pj_);
  proj_context_destroy(context_);
}

std::optional<glm::dvec2> ProjReference::forward(glm::dvec2 lonlat) const {
  const auto xy = transform(PJ_FWD, lonlat);
  if (!xy) return std::nullopt;
  return *xy * outputUnitsPerRadian_;
}

std::optional<glm::dvec2> ProjReference::inverse(glm::dvec2 xy) const {
  return transform(PJ_INV, xy / outputUnitsPerRadian_);
}

std::optional<glm::dvec2> ProjReference::transform(PJ_DIRECTION direction, glm::dvec2 in) const {
  proj_errno_reset(pj_);
  const PJ_COORD out = proj_trans(pj_, direction, proj_coord(in.x, in.y, 0.0, 0.0));
  if (proj_errno(pj_) != 0 || !std::isfinite(out.xy.x) || !std::isfinite(out.xy.y)) return std::nullopt;
  return glm::dvec2(out.xy.x, out.xy.y);
}

}  // namespace strata::test
