#pragma once
#include <strata/body.hpp>
#include <strata/camera.hpp>

namespace strata::cli {

// Mouse navigation around a body: drag to orbit, right-drag to turn and tilt, scroll to zoom. Motion scales
// with altitude, so a drag moves the ground under the pointer by about as much at 10 km as at 10,000 km.
class OrbitControls {
 public:
  OrbitControls(const Body& body, Camera& camera) : body_(body), camera_(camera) {}

  void drag(double dx, double dy, int button, int viewportHeight);
  void scroll(double steps);

 private:
  const Body& body_;
  Camera& camera_;
};

}  // namespace strata::cli
