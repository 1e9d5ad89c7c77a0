#pragma once
#include <array>
#include <cstdint>
#include <optional>

#include <strata/camera.hpp>
#include <strata/gl.hpp>
#include <strata/gl/shader_library.hpp>
#include <strata/gl/shader_program.hpp>

namespace strata::pgm {

// The least height seen in a frame, read back a frame or more later for the primary reference sphere
// ([Mahsman 2010, §3.4.1], its second method). The frame's rasterisation writes each pixel's height above the body's
// radius, in displaced (scaled) metres, into an R32F texture cleared to +infinity where no terrain is
// drawn. Heights rather than radii: a float holding Mars's radius resolves 0.25 m, one holding 21 km
// resolves 2 mm, and the two are the same up to the body's radius (the thesis writes the radius
// [Mahsman 2010, §3.4.1] and the height [Mahsman 2010, §3.7.2]).
//
// reduce() folds the texture to its minimum on the GPU (plugins/geometry-pgm/pgm_least_radius.comp), copies
// it into a persistently mapped slot and sets a fence; latest() only asks the fences with a zero timeout,
// so neither ever waits for the GPU. Make and use it on the GL thread.
class VisibleRadius {
 public:
  // Frames a reduction may stay in flight: a fifth reduce() drops the oldest unread one.
  static constexpr std::size_t kSlots = 4;

  // For a height texture of `samples` per pixel (multisampled where over 1).
  VisibleRadius(const ShaderLibrary& library, int samples);
  ~VisibleRadius();
  VisibleRadius(const VisibleRadius&) = delete;
  VisibleRadius& operator=(const VisibleRadius&) = delete;

  // Reduces texels [0, width) x [0, height) of the R32F texture `heights` (every sample of each), drawn for
  // frame `frame`.
  void reduce(GLuint heights, int width, int height, std::uint64_t frame = 0);

  // The least height (m) of the most recent reduction the GPU has finished; the one before while the
  // newest is still running. None before the first one finishes, or when no texel of it was covered.
  std::optional<double> latest();
  // The frame the value latest() gave was drawn for.
  std::uint64_t latestFrame() const { return latestFrame_; }

 private:
  void collect(std::size_t slot);

  ShaderProgram program_;
  GLuint least_ = 0;     // the shader's atomic minimum, on the GPU
  GLuint readback_ = 0;  // kSlots copies of it, mapped
  const std::uint32_t* mapped_ = nullptr;
  std::array<GLsync, kSlots> fences_{};
  std::array<std::uint64_t, kSlots> frames_{};
  std::size_t next_ = 0;  // the slot the next reduce() writes: also the oldest one in flight
  std::optional<double> latest_;
  std::uint64_t latestFrame_ = 0;
};

// Whether a least visible height measured in view `measured` may stand for view `current`: the thesis
// uses the last frame's [Mahsman 2010, §3.4.1], which holds while the view moves little from frame to
// frame; after a jump (a new viewpoint, a turn) lower terrain may have come into view, and a primary
// sphere above it would pull the mesh in from the screen's edges (the shrinking of
// [Mahsman 2010, §3.3, Fig. 3.11]). Little is: the eye moved by under kSightMove of its height above the
// minimum sphere, the view turned by under kSightTurn of its vertical field of view, and the frame's size
// and field of view are the same.
constexpr double kSightMove = 0.05;
constexpr double kSightTurn = 0.05;
bool sameSight(const View& measured, const View& current, double minimumRadius);

// The primary radius for this frame ([Mahsman 2010, §3.4.1], which leaves the first frame and r_p < d
// unsaid): the body's radius plus the last frame's least visible height, or plus the lowest height the body
// has (the minimum sphere) while there is none, on the first frame or when nothing was drawn; then kept
// below the eye by clampPrimaryRadius.
double primaryRadius(std::optional<double> latestHeight, double bodyRadius, double lowest, double eyeDistance);

}  // namespace strata::pgm
