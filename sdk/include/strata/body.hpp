#pragma once
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// The planet or moon a pipeline shows: a sphere of the given mean radius. Planet-fixed coordinates are
// geocentric with +z toward the north pole and +x toward longitude 0 on the equator (PROJ's geocentric
// convention; seed 000 uses +y north, see docs/architecture.md).
struct Body {
  std::string name = "Earth";
  double radius = 6371000.0;  // m; the IUGG mean Earth radius
};

}  // namespace strata
STRATA_EXPORTS_END
