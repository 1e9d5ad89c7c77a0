// Recognising a CRS as a registered projection: through its PROJ string, which names the method
// (+proj=) and its parameters in one vocabulary for WKT, EPSG codes and PROJ strings alike.
#include <cpl_conv.h>
#include <ogr_spatialref.h>

#include <strata/crs.hpp>
#include <strata/plugin/plugin_registry.hpp>

#include "projection/projection_terms.hpp"

namespace strata {
namespace {

const char* kReprojectFix =
    "reproject it into one of Strata's projections with `strata tile in.tif out.tif` (it picks the best suited), "
    "or give the source's `projection` when the file's CRS is wrong";

std::string typeList(const PluginRegistry& plugins) {
  std::string list;
  for (const ProjectionDeclaration* type : plugins.projections()) list += (list.empty() ? "" : ", ") + type->type;
  return list;
}

}  // namespace

std::string projStringOf(const OGRSpatialReference& crs) {
  char* text = nullptr;
  const OGRErr status = crs.exportToProj4(&text);
  std::string proj = status == OGRERR_NONE && text ? text : "";
  CPLFree(text);
  return proj;
}

std::unique_ptr<Projection> projectionOfCrs(const PluginRegistry& plugins, const OGRSpatialReference& crs,
                                            const SourceLocation& where) {
  const std::string proj = projStringOf(crs);
  if (proj.empty())
    throw Error(where,
                std::string("the CRS '") + (crs.GetName() ? crs.GetName() : "?") +
                    "' has no PROJ form: it is incomplete, or a kind PROJ cannot use",
                kReprojectFix);
  const ProjParameters terms = ProjParameters::parse(proj);
  // The built-in forms produce metres (degrees for geographic CRSs) on east/north axes from Greenwich.
  if (!plainFrame(terms))
    throw Error(where, "the CRS " + proj + " measures map coordinates in other units, axes or from another meridian",
                "reproject it with `strata tile in.tif out.tif`, which writes metres east and north of Greenwich");
  const Ellipsoid ellipsoid{crs.GetSemiMajor(), crs.GetInvFlattening()};
  const ProjectionDeclaration* type = plugins.projectionForProjName(terms.name());
  std::unique_ptr<Projection> projection;
  try {
    projection = type ? type->create(terms, ellipsoid) : nullptr;
  } catch (const Error& error) {
    throw Error(where, "the CRS " + proj + ": " + error.problem(), error.fix());
  }
  if (!projection)
    throw Error(where, "the CRS " + proj + " is not one of the projections Strata composes (" + typeList(plugins) + ")",
                kReprojectFix);
  return projection;
}

std::unique_ptr<Projection> projectionOfCrs(const PluginRegistry& plugins, const std::string& text,
                                            const SourceLocation& where) {
  OGRSpatialReference crs;
  if (crs.SetFromUserInput(text.c_str()) != OGRERR_NONE)
    throw Error(where, "'" + text + "' is not a coordinate reference system GDAL can read",
                "give WKT, a PROJ string such as '+proj=stere +lat_0=-90 +lat_ts=-71 +R=3396190', or 'EPSG:<code>'");
  return projectionOfCrs(plugins, crs, where);
}

std::unique_ptr<Projection> geographicProjection(const PluginRegistry& plugins) {
  return projectionOfCrs(plugins, "+proj=longlat +R=1", SourceLocation{"(geographic raster)"});
}

}  // namespace strata
