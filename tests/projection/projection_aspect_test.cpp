// Which region each built-in projection samples best (ProjectionAspect), from its PROJ terms, as
// composite.projection_quality's latitude method reads it: cylindrical maps their equator, azimuthal maps
// centred on a pole that pole, and the others (oblique and equatorial azimuthal maps, tilted cameras, HEALPix)
// none.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include <strata/plugin/healpix_pyramid.hpp>

#include "projection_cases.hpp"

namespace strata::test {
namespace {

using Aspect = ProjectionAspect;

void expectAspects(const std::vector<std::pair<std::string, Aspect>>& cases, const Ellipsoid& ellipsoid) {
  for (const auto& [terms, aspect] : cases) {
    const std::unique_ptr<Projection> projection = makeProjection(terms, ellipsoid);
    ASSERT_NE(projection, nullptr) << terms;
    EXPECT_EQ(projection->aspect(), aspect) << terms;
  }
}

TEST(ProjectionAspect, CylindricalMapsSampleTheirEquator) {
  // eqc's +lat_0 moves the origin only, and +lat_ts the true-scale parallels: still the normal aspect.
  expectAspects({{"+proj=longlat", Aspect::Equatorial},
                 {"+proj=latlong +lon_0=180", Aspect::Equatorial},
                 {"+proj=eqc", Aspect::Equatorial},
                 {"+proj=eqc +lat_ts=30 +lat_0=10", Aspect::Equatorial}},
                kMars);
}

TEST(ProjectionAspect, PolarStereographicMapsSampleTheirPole) {
  expectAspects({{"+proj=stere +lat_0=90", Aspect::NorthPolar},
                 {"+proj=stere +lat_0=-90 +lat_ts=-71", Aspect::SouthPolar},
                 {"+proj=ups", Aspect::NorthPolar},
                 {"+proj=ups +south", Aspect::SouthPolar}},
                kWgs84);
}

TEST(ProjectionAspect, AzimuthalMapsSampleTheirPoleOnlyWhenCentredOnIt) {
  // Within PROJ's 1e-10 rad of the pole a centre is the pole; 1e-4 degrees away it is oblique.
  expectAspects({{"+proj=ortho +lat_0=90", Aspect::NorthPolar},
                 {"+proj=ortho +lat_0=-89.99999999999", Aspect::SouthPolar},
                 {"+proj=ortho +lat_0=89.9999", Aspect::Other},
                 {"+proj=ortho +lat_0=0", Aspect::Other},  // the equator's point at lon_0, not the equator
                 {"+proj=nsper +h=35786000 +lat_0=-90", Aspect::SouthPolar},
                 {"+proj=nsper +h=35786000 +lat_0=45", Aspect::Other},
                 {"+proj=tpers +h=1000000 +lat_0=90", Aspect::NorthPolar},
                 {"+proj=tpers +h=1000000 +lat_0=90 +tilt=20 +azi=30", Aspect::Other}},
                kMoon);
}

TEST(ProjectionAspect, HealpixSamplesNoRegionBest) {
  expectAspects({{"+proj=healpix", Aspect::Other}}, kMars);
  const std::shared_ptr<const Projection> plane = makeProjection("+proj=healpix", kMars);
  EXPECT_EQ(healpix::stripProjection(plane)->aspect(), Aspect::Other);
}

}  // namespace
}  // namespace strata::test
