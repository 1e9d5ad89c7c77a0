#include <OpenColorIO/OpenColorIO.h>
#include <gdal.h>
#include <proj.h>

#include <strata/host/library_versions.hpp>
#include <strata/version.hpp>

namespace strata {

std::vector<std::pair<std::string, std::string>> libraryVersions() {
  return {{"Strata", kVersionString},
          {"GDAL", GDALVersionInfo("RELEASE_NAME")},
          {"PROJ", proj_info().release},
          {"OpenColorIO", OCIO_NAMESPACE::GetVersion()},
          {"yaml-cpp", STRATA_YAML_CPP_VERSION}};
}

}  // namespace strata
