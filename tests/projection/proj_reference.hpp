#pragma once
// PROJ itself, through its C API: the reference every projection is compared with.
#include <optional>
#include <string>

#include <proj.h>
#include <glm/vec2.hpp>

namespace strata::test {

class ProjReference {
 public:
  // Throws std::runtime_error with PROJ's message when PROJ refuses `definition`.
  explicit ProjReference(const std::string& definition);
  ~ProjReference();
  ProjReference(const ProjReference&) = delete;
  ProjReference& operator=(const ProjReference&) = delete;

  // lon/lat in radians to map coordinates in the raster's units: PROJ's metres, or for a geographic
  // definition (whose PROJ output is in radians) degrees. Empty where PROJ reports an error.
  std::optional<glm::dvec2> forward(glm::dvec2 lonlat) const;
  std::optional<glm::dvec2> inverse(glm::dvec2 xy) const;

 private:
  std::optional<glm::dvec2> transform(PJ_DIRECTION direction, glm::dvec2 in) const;

  PJ_CONTEXT* context_ = nullptr;
  PJ* pj_ = nullptr;
  double outputUnitsPerRadian_ = 1.0;  // 180 / pi where PROJ's map side is angular
};

}  // namespace strata::test
