#pragma once
#include <strata/export.hpp>
#include <strata/gl.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// Times GPU work between begin() and end() with a GL_TIME_ELAPSED query, on the GL thread. Reading the
// time waits for the GPU to finish that work, so read it after the frame, when statistics are wanted.
class GpuTimer {
 public:
  GpuTimer();
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void begin();
  void end();
  double milliseconds() const;  // of the last begin()..end(); 0 before the first

 private:
  GLuint query_ = 0;
  bool timed_ = false;
};

}  // namespace strata
STRATA_EXPORTS_END
