// The body's outline (plugins/output-image/body_outline.hpp), within which output.image composes its layers:
// every pixel with a sample on the sphere has its centre inside the outline, and the outline holds little
// else. Judged pixel by pixel at 320 x 180 against exact ray-sphere intersections in double, through the
// pixel's centre and its four corners (the samples of any pattern lie within them): from 20,000 km with the
// body in the middle, from 8,000 km with it at the frame's edge, and from 3,000 km tilted toward the horizon;
// from 2,000 km the body holds the frame, and from 5 km the cone is too wide for a disc.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "body_outline.hpp"

namespace strata::image {
namespace {

constexpr double kRadius = 6371000.0;
constexpr int kWidth = 320, kHeight = 180;

// The planet-fixed ray through frame point (x, y) (pixels from the top left).
glm::dvec3 rayThrough(const View& view, double x, double y) {
  const double up = std::tan(0.5 * view.verticalFov), right = up * view.width / view.height;
  const glm::dvec3 inEye((2.0 * x / view.width - 1.0) * right, (1.0 - 2.0 * y / view.height) * up, -1.0);
  return glm::normalize(glm::transpose(view.planetToEye) * inEye);
}

bool hitsSphere(const glm::dvec3& eye, const glm::dvec3& ray) {
  const double b = glm::dot(eye, ray), c = glm::dot(eye, eye) - kRadius * kRadius;
  return b < 0.0 && b * b >= c;
}

// Whether frame point (x, y) lies inside the fan's convex polygon, all of whose points are in front of the eye.
bool insideFan(const std::vector<glm::vec4>& fan, double x, double y) {
  const glm::dvec2 point(2.0 * x / kWidth - 1.0, 1.0 - 2.0 * y / kHeight);
  bool left = true, right = true;  // of every edge: inside, whichever way the rim turns
  for (std::size_t i = 1; i + 1 < fan.size(); ++i) {
    const glm::dvec2 a = glm::dvec2(fan[i]) / double(fan[i].w), b = glm::dvec2(fan[i + 1]) / double(fan[i + 1].w);
    const glm::dvec2 edge = b - a, to = point - a;
    const double turn = edge.x * to.y - edge.y * to.x;
    left = left && turn >= 0.0;
    right = right && turn <= 0.0;
  }
  return left || right;
}

struct Judged {
  int onBody = 0;  // pixels with a sample on the sphere
  int missed = 0;  // of those, outside the outline
  int inside = 0;  // pixels inside the outline
  int farOff = 0;  // of those, more than 3 pixels' angle beyond the limb
};

Judged judge(const View& view, const BodyOutline& outline) {
  Judged judged;
  const double distance = glm::length(view.eye);
  const glm::dvec3 axis = -view.eye / distance;
  const double limb = std::asin(kRadius / distance), pixel = view.verticalFov / view.height;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      bool onBody = false;
      for (const glm::dvec2 at :
           {glm::dvec2(cx, cy), glm::dvec2(x, y), glm::dvec2(x + 1, y), glm::dvec2(x, y + 1), glm::dvec2(x + 1, y + 1)})
        onBody = onBody || hitsSphere(view.eye, rayThrough(view, at.x, at.y));
      const bool inside = insideFan(outline.fan, cx, cy);
      judged.onBody += int(onBody);
      judged.missed += int(onBody && !inside);
      judged.inside += int(inside);
      const double off = std::acos(std::clamp(glm::dot(rayThrough(view, cx, cy), axis), -1.0, 1.0)) - limb;
      judged.farOff += int(inside && off > 3.0 * pixel + 0.02 * limb);  // the polygon's corners reach 2 % out
    }
  return judged;
}

TEST(BodyOutline, HoldsEveryPixelWithASampleOnTheBodyAndLittleElse) {
  const Body earth{"Earth", kRadius};
  for (const Camera& camera :
       {Camera{.lon = 10, .lat = 20, .altitude = 2.0e7, .fov = 36},
        Camera{.lon = 137.4, .lat = -4.6, .altitude = 8.0e6, .heading = 40, .tilt = 25, .fov = 36},
        Camera{.lon = -170, .lat = 75, .altitude = 3.0e6, .heading = 200, .tilt = 30, .fov = 36}}) {
    const View view = makeView(earth, camera, kWidth, kHeight);
    const BodyOutline outline = bodyOutline(view, kRadius);
    ASSERT_FALSE(outline.wholeFrame) << camera.altitude << " m up";
    for (const glm::vec4& point : outline.fan) ASSERT_GT(point.w, 0.0f) << "the judge takes points in front";
    const Judged judged = judge(view, outline);
    std::printf("%.0f m up: %d pixels on the body, %d of them outside; %d inside, %d far off the limb\n",
                camera.altitude, judged.onBody, judged.missed, judged.inside, judged.farOff);
    EXPECT_GT(judged.onBody, 1000);
    EXPECT_LT(judged.onBody, kWidth * kHeight) << "the body shows beside sky";
    EXPECT_EQ(judged.missed, 0);
    EXPECT_EQ(judged.farOff, 0);
  }
}

TEST(BodyOutline, IsTheWholeFrameWhereTheBodyHoldsItOrTheEyeIsClose) {
  const Body earth{"Earth", kRadius};
  for (const Camera& camera : {Camera{.lon = 10, .lat = 20, .altitude = 2.0e6, .fov = 36},
                               Camera{.lon = 10, .lat = 20, .altitude = 5000, .tilt = 60, .fov = 36},
                               Camera{.lon = 10, .lat = 20, .altitude = 5000, .tilt = 95, .fov = 36}}) {
    const BodyOutline outline = bodyOutline(makeView(earth, camera, kWidth, kHeight), kRadius);
    EXPECT_TRUE(outline.wholeFrame) << camera.altitude << " m up, tilted " << camera.tilt;
    EXPECT_EQ(outline.fan.size(), 3u) << "one triangle over the frame";
  }
}

}  // namespace
}  // namespace strata::image
