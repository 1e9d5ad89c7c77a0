#pragma once
#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include <strata/plugin/layer.hpp>

#include "cutaway.hpp"

namespace strata::composite {

// A stack of height layers, top first (an ice sheet's surface over its bedrock, the sea's surface over the
// sea floor), as one height layer with its upper layers peeled away where a cutaway says
// ([Kooima 2008, §1.1, ch. 6], layered data peeling). A layer's material lies between its surface and the
// next one's; the last layer is the floor, beneath which nothing is peeled.
// - Each surface lies no lower than the one beneath: where a layer's data put it lower (the sea's surface
//   over land) or it has none, it is absent there, with no thickness.
// - Inside the cut, the `layers` upper layers are taken away and `depth` metres more below the surface that
//   exposes, never below the floor: the surface shown is max(floor, surface[layers] - depth).
// - Outside it the top surface shows; across the cutaway's edge the surface slopes from one to the other.
// The peel and the cutaway are uniforms: changing them rebuilds no program.
class PeelLayer : public Layer {
 public:
  struct Peel {
    int layers = 1;      // how many of the upper layers the cut takes away, at most all but the floor
    double depth = 0.0;  // m cut below the surface they expose
  };

  // `stack`: two or more height layers, top first. `radius`: the body's.
  PeelLayer(const std::string& nodeId, std::vector<const Layer*> stack, Peel peel, Cutaway cutaway, double radius);

  LayerKind kind() const override { return LayerKind::Height; }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;
  void setPageDemand(PageDemand demand) const override;
  std::optional<ValueRange> valueRange() const override { return spanningRange(stack_); }
  std::uint64_t revision() const override { return summedRevision(stack_) + repeeled_; }
  // A new peel and cutaway for the next frame: their values are uniforms.
  void repeel(Peel peel, Cutaway cutaway);

  // What composite.peeled_surface builds on, in glsl():
  //   float <stackFunction()>(SurfacePoint p, out float surfaces[stackSize()])
  // the surfaces of the stack at p, top first (m), returning the coverage (the greatest of the layers'), and
  //   float <shownFunction()>(SurfacePoint p, float surfaces[stackSize()])
  // the height of the surface shown there.
  std::size_t stackSize() const { return stack_.size(); }
  std::string stackFunction() const { return prefix_ + "_stack"; }
  std::string shownFunction() const { return prefix_ + "_shown"; }

 private:
  std::string stacked() const;
  std::string shown() const;

  std::string prefix_;
  std::vector<const Layer*> stack_;
  Peel peel_;
  Cutaway cutaway_;
  std::atomic<std::uint64_t> repeeled_{0};  // times repeel() changed the peel or the cutaway
  double radius_;
};

}  // namespace strata::composite
