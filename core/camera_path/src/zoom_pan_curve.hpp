#pragma once

// The optimal path between two views of van Wijk and Nuij 2003, "Smooth and efficient zooming and panning"
// (IEEE InfoVis). In their flat-world model a view is a position u along the ground and a width w,
// both in one unit. The path from (0, w0) to (u1, w1) that minimises the perceived motion zooms out while it
// pans and back in toward its end; parametrised by its length s in their metric, travelling it at constant
// speed moves at a constant perceived speed.
namespace strata::paths {

class ZoomPanCurve {
 public:
  // rho: the trade-off between zooming and panning (their users preferred about 1.42).
  ZoomPanCurve(double u1, double w0, double w1, double rho);

  double length() const { return length_; }  // S
  bool pans() const { return pans_; }        // false over one point: a pure zoom, u = 0 throughout
  double ground(double s) const;             // u(s), from 0 to u1
  double width(double s) const;              // w(s), from w0 to w1

 private:
  double w0_, w1_, rho_;
  bool pans_;
  double r0_ = 0.0;
  double length_ = 0.0;
};

}  // namespace strata::paths
