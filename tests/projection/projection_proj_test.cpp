// The built-in projections in double precision against PROJ itself (proj_trans, PJ_FWD and PJ_INV) on
// dense samples over each projection's whole domain, and their round trips. The tolerance is 1e-6 of a
// texel of a raster 40000 texels across the projection's full x range (projection_cases.hpp), e.g. for
// HEALPix on Earth 2 pi R / 40000 * 1e-6 = 1.0 mm (R = 6371007 m, the authalic radius), for an orthographic
// view of the Moon 2 a / 40000 * 1e-6 = 87 um, for geographic rasters 360 / 40000 * 1e-6 = 9e-9 degrees.
// Where PROJ and Strata disagree on whether a point maps, the point must lie within 1e-9 rad (forward) or
// 1e-9 of the full range (inverse) of where the projection stops being defined (the rim of the visible
// hemisphere, the horizon: the two tests of visibility round differently), or PROJ's answer must lie
// outside the compared window (the opposite pole of a polar stereographic map, which PROJ's ellipsoidal
// stere puts some 1e22 m away), or behind a tilted camera (below).
//
// Two known inaccuracies of PROJ 9.1 widen the tolerance where they apply:
// - HEALPix near the poles: PROJ forms 1 - |sin(beta)| by subtraction, an error d of some 4 u (u = 2^-53)
//   that becomes sqrt(3 d), or 3 d / (2 sigma) where larger than it, in sigma = sqrt(3 (1 - |sin(beta)|)),
//   and R pi / 2 times that on the map: up to 0.37 m on Earth at the poles themselves, 3e-10 of a texel one
//   degree from them. Strata forms 1 - |sin(beta)| without the subtraction.
// - HEALPix on an ellipsoid, inverse: PROJ's inverse authalic latitude is Snyder's series to e^6, whose
//   truncation error reaches 2.5e-10 rad on WGS84 (at 21 degrees; the next terms of the series), 1.6e-6 of a
//   texel. inverse() solves for the latitude exactly instead; there it is held to PJ_INV's tolerance plus
//   2e-6 texels, and to 1e-6 texels against PJ_FWD (the residual |PJ_FWD(inverse(xy)) - xy|).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>
#include <sstream>

#include <glm/trigonometric.hpp>

#include "projection_cases.hpp"

namespace strata::test {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kToleranceInTexels = 1e-6;
constexpr double kProjSeriesTruncationInTexels = 2e-6;

// PROJ's rounding in HEALPix's sigma near the poles, in map units (see above).
double projPolarRounding(const Projection& projection, glm::dvec2 lonlat) {
  if (projection.type() != "healpix") return 0.0;
  const double d = 4.0 * 0x1p-53;
  const double oneMinusSine = std::pow(std::cos(lonlat.y), 2) / (1.0 + std::abs(std::sin(lonlat.y)));
  const double sigma = std::sqrt(3.0 * oneMinusSine);
  return projection.glslMapScale() * kPi / 2.0 * std::min(std::sqrt(3.0 * d), 1.5 * d / sigma);
}

// PROJ's truncated inverse authalic latitude (see above), in texels.
double projInverseAllowance(const ProjectionCase& projectionCase, const Projection& projection) {
  return projection.type() == "healpix" && projectionCase.ellipsoid.inverseFlattening != 0.0
             ? kProjSeriesTruncationInTexels
             : 0.0;
}

// PROJ's tpers maps points behind the tilted camera too, mirrored through infinity; forward() and inverse()
// leave them empty. This tells such points by PROJ's vertical perspective (nsper) and the depth term of
// tpers (Snyder 1987, ch. 23).
class BehindTiltedCamera {
 public:
  explicit BehindTiltedCamera(const ProjectionCase& projectionCase) {
    const ProjParameters terms = ProjParameters::parse(projectionCase.terms);
    if (terms.name() != "tpers") return;
    std::string vertical = referenceDefinition(projectionCase);
    vertical.replace(vertical.find("tpers"), 5, "nsper");
    vertical_ = std::make_unique<ProjReference>(vertical);
    origin_ = {terms.real("x_0", 0.0), terms.real("y_0", 0.0)};
    a_ = projectionCase.ellipsoid.semiMajorAxis;
    height_ = terms.real("h", 0.0) / a_;
    tilt_ = glm::radians(terms.real("tilt", 0.0));
    azimuth_ = glm::radians(terms.real("azi", 0.0));
  }

  bool operator()(glm::dvec2 lonlat) const {
    const auto vertical = vertical_ ? vertical_->forward(lonlat) : std::nullopt;
    if (!vertical) return false;
    const glm::dvec2 plane = (*vertical - origin_) / a_;
    const double along = plane.y * std::cos(azimuth_) + plane.x * std::sin(azimuth_);
    return along * std::sin(tilt_) / height_ + std::cos(tilt_) <= 1e-12;
  }

 private:
  std::unique_ptr<ProjReference> vertical_;
  glm::dvec2 origin_{0.0};
  double a_ = 1.0;
  double height_ = 1.0;
  double tilt_ = 0.0;
  double azimuth_ = 0.0;
};

// Collects the first few unexplained samples for the failure message.
class Disagreements {
 public:
  void add(const std::string& what, glm::dvec2 at) {
    if (count_++ < 5) text_ << "\n  " << what << " at (" << at.x << ", " << at.y << ")";
  }
  int count() const { return count_; }
  std::string text() const { return text_.str(); }

 private:
  int count_ = 0;
  std::ostringstream text_;
};

class AgainstProj : public testing::TestWithParam<ProjectionCase> {
 protected:
  void SetUp() override {
    projection_ = makeProjection(GetParam());
    ASSERT_NE(projection_, nullptr) << GetParam().terms;
    proj_ = std::make_unique<ProjReference>(referenceDefinition(GetParam()));
    window_ = mapWindow(GetParam(), *projection_, *proj_);
  }

  double tolerance() const { return kToleranceInTexels * window_.texel(); }

  void report(const std::string& what, double worst, int compared) {
    std::cout << GetParam().name << " " << what << ": worst " << worst << " map units = " << worst / window_.texel()
              << " texels of " << window_.texel() << " (" << compared << " samples, tolerance " << tolerance() << ")\n";
    RecordProperty(what + "_worst_texels", std::to_string(worst / window_.texel()));
  }

  // Whether inverse() changes between defined and empty within `delta` of `xy`.
  bool nearInverseEdge(glm::dvec2 xy, double delta) const {
    const bool here = projection_->inverse(xy).has_value();
    for (glm::dvec2 step :
         {glm::dvec2(delta, 0.0), glm::dvec2(-delta, 0.0), glm::dvec2(0.0, delta), glm::dvec2(0.0, -delta)})
      if (projection_->inverse(xy + step).has_value() != here) return true;
    return false;
  }

  std::unique_ptr<Projection> projection_;
  std::unique_ptr<ProjReference> proj_;
  MapWindow window_;
};

TEST_P(AgainstProj, ForwardMatchesProj) {
  const BehindTiltedCamera behindCamera(GetParam());
  Disagreements disagreements;
  double worst = 0.0, worstWherePrecise = 0.0;
  int compared = 0;
  for (glm::dvec2 lonlat : lonlatSamples(*proj_, window_, 720, 361, 400)) {
    const auto mine = projection_->forward(lonlat);
    const auto theirs = proj_->forward(lonlat);
    if (mine.has_value() != theirs.has_value()) {
      const bool explained =
          nearRim(*projection_, lonlat, 1e-9) || (theirs && (!window_.contains(*theirs) || behindCamera(lonlat)));
      if (!explained) disagreements.add(mine ? "PROJ undefined" : "forward() empty", lonlat);
      continue;
    }
    if (!mine || !window_.contains(*theirs)) continue;
    const double error = mapDistance(*projection_, *mine, *theirs);
    const double projRounding = projPolarRounding(*projection_, lonlat);
    if (error > tolerance() + projRounding) disagreements.add("error " + std::to_string(error), lonlat);
    worst = std::max(worst, error);
    if (projRounding < tolerance()) worstWherePrecise = std::max(worstWherePrecise, error);
    ++compared;
  }
  report("forward", worst, compared);
  report("forward_where_proj_is_precise", worstWherePrecise, compared);
  EXPECT_GT(compared, 20000);
  EXPECT_EQ(disagreements.count(), 0) << disagreements.text();
}

TEST_P(AgainstProj, InverseMatchesProj) {
  const BehindTiltedCamera behindCamera(GetParam());
  const double allowance = projInverseAllowance(GetParam(), *projection_) * window_.texel();
  Disagreements disagreements;
  double worst = 0.0, worstResidual = 0.0;
  int compared = 0;
  for (glm::dvec2 xy : mapSamples(window_, 400)) {
    const auto mine = projection_->inverse(xy);
    const auto theirs = proj_->inverse(xy);
    if (mine.has_value() != theirs.has_value()) {
      const bool explained = nearInverseEdge(xy, 1e-9 * window_.fullRangeX) || (theirs && behindCamera(*theirs));
      if (!explained) disagreements.add(mine ? "PROJ undefined" : "inverse() empty", xy);
      continue;
    }
    if (!mine) continue;
    // Measured in map units: where PROJ's forward puts the two answers.
    const auto mineMapped = proj_->forward(*mine), theirsMapped = proj_->forward(*theirs);
    if (!mineMapped || !theirsMapped) {
      disagreements.add("PROJ cannot map the answers back", xy);
      continue;
    }
    const double error = mapDistance(*projection_, *mineMapped, *theirsMapped);
    const double residual = mapDistance(*projection_, *mineMapped, xy);
    if (error > tolerance() + allowance) disagreements.add("error " + std::to_string(error), xy);
    if (residual > tolerance()) disagreements.add("residual " + std::to_string(residual), xy);
    worst = std::max(worst, error);
    worstResidual = std::max(worstResidual, residual);
    ++compared;
  }
  report("inverse", worst, compared);
  report("inverse_residual", worstResidual, compared);
  EXPECT_GT(compared, 10000);
  EXPECT_EQ(disagreements.count(), 0) << disagreements.text();
}

TEST_P(AgainstProj, RoundTrips) {
  Disagreements disagreements;
  double worst = 0.0;
  int compared = 0;
  const auto check = [&](glm::dvec2 xy, const std::string& what) {
    const auto lonlat = projection_->inverse(xy);
    const auto back = lonlat ? projection_->forward(*lonlat) : std::nullopt;
    if (!back) return disagreements.add(what + ": no way back", xy);
    const double error = mapDistance(*projection_, *back, xy);
    if (error > tolerance()) disagreements.add(what + ": error " + std::to_string(error), xy);
    worst = std::max(worst, error);
    ++compared;
  };
  for (glm::dvec2 lonlat : lonlatSamples(*proj_, window_, 720, 361, 0)) {
    const auto xy = projection_->forward(lonlat);
    const bool nearEdge =
        nearRim(*projection_, lonlat, 1e-9) || nearSeam(*projection_, lonlat, 1e-9, 0.01 * window_.fullRangeX);
    if (xy && window_.contains(*xy) && !nearEdge) check(*xy, "forward then inverse");
  }
  for (glm::dvec2 xy : mapSamples(window_, 400))
    if (projection_->inverse(xy)) check(xy, "inverse then forward");
  report("round_trip", worst, compared);
  EXPECT_EQ(disagreements.count(), 0) << disagreements.text();
}

TEST_P(AgainstProj, ProjStringIsTheSameMapping) {
  const ProjReference own(projection_->projString());
  double worst = 0.0;
  for (glm::dvec2 lonlat : lonlatSamples(*proj_, window_, 180, 91, 100)) {
    const auto mine = own.forward(lonlat), theirs = proj_->forward(lonlat);
    ASSERT_EQ(mine.has_value(), theirs.has_value()) << projection_->projString();
    if (mine && window_.contains(*theirs)) worst = std::max(worst, mapDistance(*projection_, *mine, *theirs));
  }
  EXPECT_LE(worst, tolerance()) << projection_->projString();
}

// The seams of HEALPix's polar triangles, the meridians lon_0 + k 90 degrees where the map is interrupted: on
// either side of them and on them. On the antimeridian itself forward() gives the west edge's image (the wrap
// interval is half-open); PROJ gives either edge's, depending on how it rounds the longitude into its range,
// so there the reference is PROJ's a picoradian east of it.
TEST(HealpixSeams, MatchProjOnEitherSideAndOnThem) {
  for (const ProjectionCase& projectionCase : projectionCases()) {
    if (!projectionCase.terms.starts_with("+proj=healpix")) continue;
    const auto projection = makeProjection(projectionCase);
    const ProjReference proj(referenceDefinition(projectionCase));
    const double tolerance = kToleranceInTexels * *projection->periodX() / kTexelsAcross;
    const double lon0 = glm::radians(projectionCase.centre.x);
    for (double lat : {42.0, 50.0, 70.0, 85.0, 89.9, -42.0, -60.0, -89.9})
      for (int k = -2; k <= 1; ++k)
        for (double offset : {-1e-9, 0.0, 1e-9}) {
          const glm::dvec2 lonlat(lon0 + k * kPi / 2.0 + offset, glm::radians(lat));
          const bool antimeridian = k == -2 && offset == 0.0;
          const auto mine = projection->forward(lonlat);
          const auto theirs = proj.forward(lonlat + glm::dvec2(antimeridian ? 1e-12 : 0.0, 0.0));
          ASSERT_TRUE(mine && theirs);
          EXPECT_LE(mapDistance(*projection, *mine, *theirs), tolerance + projPolarRounding(*projection, lonlat))
              << projectionCase.name << " at latitude " << lat << ", seam " << k << ", offset " << offset;
        }
  }
}

std::string caseName(const testing::TestParamInfo<ProjectionCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Builtin, AgainstProj, testing::ValuesIn(projectionCases()), caseName);

}  // namespace
}  // namespace strata::test
