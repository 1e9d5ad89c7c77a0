#pragma once
#include <string>

#include <glm/glm.hpp>
#include <strata/camera.hpp>
#include <strata/plugin/layer.hpp>

namespace strata::procedural {

// A checkerboard laid on the ground: square cells `cell` metres along the meridian and along the parallel
// through `anchor` (longitude and latitude, rad), counted from the anchor. It shows how precisely a
// pipeline places the surface: from 2 m above an Earth-sized body a 1 cm board stays crisp and still only
// if every pixel's longitude and latitude are right to a millimetre (issue 4). Counting cells from the
// anchor to a point near the eye would take more digits than float has, so the CPU counts to the frame's
// reference point (View::reference) in double and the GPU only adds the cells from there
// (SurfacePoint::fromReference). Each sample is box-filtered over its footprint, so the board never aliases.
class CheckerLayer : public Layer {
 public:
  CheckerLayer(const std::string& nodeId, glm::dvec2 anchor, double cell, double radius);

  // Counts the cells from the anchor to the view's reference point; before every frame.
  void follow(const View& view);

  LayerKind kind() const override { return LayerKind::Color; }
  std::string samplingFunction() const override { return prefix_; }
  std::string glsl() const override;
  void bind(ShaderProgram& program, TextureUnits& units) const override;

 private:
  std::string prefix_;  // GLSL identifier prefix unique to the node
  glm::dvec2 anchor_;
  glm::dvec2 cellsPerRadian_;    // along longitude (at the anchor's latitude) and latitude
  glm::vec2 referenceFraction_;  // the reference point's position within its cell, 0 to 1 on each axis
  int referenceParity_ = 0;      // 1 when the reference point's cell is dark
};

}  // namespace strata::procedural
