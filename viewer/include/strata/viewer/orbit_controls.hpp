#pragma once
#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/window/glfw_window.hpp>

namespace strata::viewer {

// Navigation around a body: drag to orbit, right-drag to turn and tilt, scroll to zoom toward the point
// under the pointer; the arrows orbit, + and - zoom, W and S fly along the line of sight. Motion scales with altitude,
// so a drag moves the ground under the pointer by about as much at 10 km as at 10,000 km, and an arrow a tenth of the
// view's height.
class OrbitControls {
 public:
  OrbitControls(const Body& body, Camera& camera) : body_(body), camera_(camera) {}

  void drag(double dx, double dy, int button, int viewportHeight);
  void scroll(double steps);
  // Zooms as scroll() does, moving toward (or away from) the ground under pixel (x, y) of a viewport
  // width x height, so that it stays about under the pointer; where the pointer is off the body, as scroll().
  void scrollToward(double steps, double x, double y, int width, int height);
  // An arrow, +, -, W or S, for a viewport `viewportHeight` pixels high; Home is the caller's (its camera).
  void key(NavigationKey key, int viewportHeight);
  // Flies `share` of the altitude along the line of sight (negative: back): down and forward as the view
  // is tilted, so that a tilted view approaches what it looks at.
  void fly(double share);

 private:
  const Body& body_;
  Camera& camera_;
};

}  // namespace strata::viewer
