#include "body_of_the_crs.hpp"

#include <ogr_spatialref.h>

#include <optional>

#include <strata/log.hpp>
#include <strata/named_bodies.hpp>
#include <strata/plugin/parameter.hpp>

namespace strata::gdal {
namespace {

// The semi-axes of the ellipsoid `crs` (or the file's CRS) lies on; none where there is no CRS or OGR
// does not read it (a plugin's own projection).
std::optional<NamedBody> ellipsoidOf(GDALDataset& dataset, const std::string& crs) {
  OGRSpatialReference given;
  const OGRSpatialReference* reference = dataset.GetSpatialRef();
  if (!crs.empty()) reference = given.SetFromUserInput(crs.c_str()) == OGRERR_NONE ? &given : nullptr;
  if (!reference) return std::nullopt;
  OGRErr semiMajorError = OGRERR_NONE, semiMinorError = OGRERR_NONE;
  const double a = reference->GetSemiMajor(&semiMajorError), b = reference->GetSemiMinor(&semiMinorError);
  if (semiMajorError != OGRERR_NONE || semiMinorError != OGRERR_NONE || !(a > 0.0) || !(b > 0.0)) return std::nullopt;
  return NamedBody{"", (a + b) / 2.0, a, b};
}

std::string metres(double value) { return formatValue(ParameterValue(value)) + " m"; }

// "3396190 m (Mars's)": the ellipsoid's size, and the body it is of where one fits.
std::string sizeOf(const NamedBody& ellipsoid) {
  std::string size = metres(ellipsoid.equatorialRadius);
  if (ellipsoid.polarRadius != ellipsoid.equatorialRadius) size += " by " + metres(ellipsoid.polarRadius);
  for (const NamedBody& named : namedBodies())
    if (radiusFits(named, ellipsoid.equatorialRadius) && radiusFits(named, ellipsoid.polarRadius))
      return size + " (" + named.name + "'s)";
  return size;
}

}  // namespace

void reportAnotherBody(GDALDataset& dataset, const std::string& crs, const Body& body, const SourceLocation& where) {
  const std::optional<NamedBody> ellipsoid = ellipsoidOf(dataset, crs);
  if (!ellipsoid || radiusFits(*ellipsoid, body.radius)) return;
  const std::string file = dataset.GetDescription();
  logWarning(where.str() + ": '" + file + "' lies on a body of " + sizeOf(*ellipsoid) + ", not on the pipeline's " +
                 body.name + " of " + metres(body.radius) +
                 "; it is placed by its longitudes and latitudes, so its distances scale to the body",
             "name the body the raster is of (body: {name: Mars}); or, if its CRS is wrong, assign the right one: "
             "gdal_edit.py -a_srs CRS " +
                 file);
}

}  // namespace strata::gdal
