// CameraPath::flight, van Wijk and Nuij's zooming and panning along a great circle, in double precision.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/glm.hpp>

#include <strata/host/camera_path.hpp>

namespace strata {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

glm::dvec3 groundPoint(const Camera& camera) { return unitNormal(camera.lon * kDegree, camera.lat * kDegree); }
double arc(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// From a mountain in the Alps to one in the Andes, 5 km up at both ends.
CameraFlight alpsToAndes() {
  CameraFlight flight;
  flight.from = Camera{10.0, 46.0, 5000.0, 0.0, 60.0, 45.0};
  flight.to = Camera{-70.0, -33.0, 5000.0, 90.0, 60.0, 45.0};
  flight.duration = 20.0;
  return flight;
}

TEST(CameraFlightTest, StartsAndEndsAtItsCameras) {
  const CameraFlight flight = alpsToAndes();
  const CameraPath path = CameraPath::flight(flight, Body{});
  EXPECT_EQ(path.start(), 0.0);
  EXPECT_EQ(path.end(), 20.0);
  for (const auto& [time, expected] : {std::pair{0.0, flight.from}, std::pair{20.0, flight.to}}) {
    const Camera at = path.at(time);
    EXPECT_NEAR(at.lon, expected.lon, 1e-9) << "t = " << time;
    EXPECT_NEAR(at.lat, expected.lat, 1e-9);
    EXPECT_NEAR(at.altitude / expected.altitude, 1.0, 1e-9);
    EXPECT_NEAR(at.heading, expected.heading, 1e-9);
    EXPECT_NEAR(at.tilt, expected.tilt, 1e-9);
  }
}

// The ground track stays on the great circle through both ends and moves forward along it.
TEST(CameraFlightTest, FollowsTheGreatCircleForward) {
  const CameraFlight flight = alpsToAndes();
  const CameraPath path = CameraPath::flight(flight, Body{});
  const glm::dvec3 from = groundPoint(flight.from), to = groundPoint(flight.to);
  const glm::dvec3 normal = glm::normalize(glm::cross(from, to));
  double farthest = 0.0, travelled = -1.0;
  for (int i = 0; i <= 2000; ++i) {
    const glm::dvec3 point = groundPoint(path.atFraction(i / 2000.0));
    farthest = std::max(farthest, std::abs(glm::dot(point, normal)));
    const double along = arc(from, point);
    EXPECT_GE(along, travelled - 1e-12) << "step " << i;
    travelled = along;
  }
  std::printf("farthest from the great circle: %.2e rad\n", farthest);
  EXPECT_LT(farthest, 1e-14);  // rad: 64 nm on the Earth
  EXPECT_NEAR(travelled, arc(from, to), 1e-12);
}

// Between two views of the same size the flight is symmetric: halfway in time it is halfway along the
// ground and at its highest, zoomed out to see about the whole distance (w = u1 / 2 cosh r0 ~ rho^2 u1 / 2).
TEST(CameraFlightTest, ZoomsOutToSeeTheWayAndBackIn) {
  const CameraFlight flight = alpsToAndes();
  const CameraPath path = CameraPath::flight(flight, Body{});
  const double distance = Body{}.radius * arc(groundPoint(flight.from), groundPoint(flight.to));
  const Camera middle = path.at(10.0);
  EXPECT_NEAR(arc(groundPoint(flight.from), groundPoint(middle)) * Body{}.radius / distance, 0.5, 1e-12);
  const double width = 2.0 * middle.altitude * std::tan(22.5 * kDegree);
  EXPECT_NEAR(width / (flight.rho * flight.rho * distance / 2.0), 1.0, 1e-3);
  EXPECT_GT(middle.altitude, path.at(9.9).altitude);
  EXPECT_GT(middle.altitude, path.at(10.1).altitude);
  // Zoomed out 3,000 times wider than at the ends, the view turns to look straight down, not past the planet.
  EXPECT_LT(middle.tilt, 60.0 / 1000.0);
}

// Over one point the flight is a pure zoom: the altitude changes by the same factor every second.
TEST(CameraFlightTest, OverOnePointZoomsAtAConstantRate) {
  CameraFlight flight;
  flight.from = Camera{30.0, 25.0, 8.0e6, 0.0, 0.0, 45.0};
  flight.to = Camera{30.0, 25.0, 8.0, 0.0, 0.0, 45.0};
  flight.duration = 6.0;
  const CameraPath path = CameraPath::flight(flight, Body{"Mars", 3396190.0});
  for (int second = 0; second <= 6; ++second) {
    EXPECT_NEAR(path.at(second).altitude / (8.0e6 * std::pow(10.0, -second)), 1.0, 1e-12) << "t = " << second;
    EXPECT_NEAR(path.at(second).lon, 30.0, 1e-12);
  }
}

// Heading turns the shorter way in a flight too: from 350 to 10 degrees through north.
TEST(CameraFlightTest, TurnsTheShorterWayRound) {
  CameraFlight flight = alpsToAndes();
  flight.from.heading = 350.0;
  flight.to.heading = 10.0;
  const CameraPath path = CameraPath::flight(flight, Body{});
  EXPECT_NEAR(std::abs(std::remainder(path.at(10.0).heading, 360.0)), 0.0, 1e-12);
  for (int i = 0; i <= 100; ++i) {
    const double heading = path.atFraction(i / 100.0).heading;
    EXPECT_TRUE(heading >= 350.0 || heading <= 10.0) << heading;
  }
}

TEST(CameraFlightTest, RefusesAntipodesAndNonPositiveDurations) {
  CameraFlight flight = alpsToAndes();
  flight.to = Camera{-170.0, -46.0, 5000.0, 0.0, 0.0, 45.0};
  EXPECT_THROW(CameraPath::flight(flight, Body{}), std::invalid_argument);
  flight = alpsToAndes();
  flight.duration = 0.0;
  EXPECT_THROW(CameraPath::flight(flight, Body{}), std::invalid_argument);
}

}  // namespace
}  // namespace strata
