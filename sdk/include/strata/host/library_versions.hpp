#pragma once
#include <strata/export.hpp>
#include <string>
#include <utility>
#include <vector>

STRATA_EXPORTS_BEGIN
namespace strata {

// Name and version of each library Strata was built with and runs on (GDAL, PROJ, OpenColorIO, yaml-cpp),
// for `strata info` and bug reports.
std::vector<std::pair<std::string, std::string>> libraryVersions();

}  // namespace strata
STRATA_EXPORTS_END
