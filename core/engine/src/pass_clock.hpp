#pragma once
#include <cstddef>
#include <vector>

#include <strata/gl.hpp>

namespace strata {

// GPU timestamps at the boundaries of a frame's passes, one GL_TIMESTAMP query each: unlike GL_TIME_ELAPSED
// queries, which may not nest, they leave a node free to time its own phases (GpuTimer) inside its pass.
// Made and used on the GL thread.
class PassClock {
 public:
  explicit PassClock(std::size_t passes);
  ~PassClock();
  PassClock(const PassClock&) = delete;
  PassClock& operator=(const PassClock&) = delete;

  // Records the GPU's time once the work submitted so far is done: boundary 0 before the first pass,
  // boundary i + 1 after pass i.
  void mark(std::size_t boundary);
  // Each pass's GPU time in the last marked frame, ms; waits for the GPU to reach the last boundary. Zeros
  // before a frame was marked.
  std::vector<double> milliseconds() const;

 private:
  std::vector<GLuint> queries_;
  bool marked_ = false;
};

}  // namespace strata
