#include <strata/gl/gpu_timer.hpp>

namespace strata {

GpuTimer::GpuTimer() { glCreateQueries(GL_TIME_ELAPSED, 1, &query_); }

GpuTimer::~GpuTimer() { glDeleteQueries(1, &query_); }

void GpuTimer::begin() { glBeginQuery(GL_TIME_ELAPSED, query_); }

void GpuTimer::end() {
  glEndQuery(GL_TIME_ELAPSED);
  timed_ = true;
}

double GpuTimer::milliseconds() const {
  if (!timed_) return 0.0;
  GLuint64 nanoseconds = 0;
  glGetQueryObjectui64v(query_, GL_QUERY_RESULT, &nanoseconds);
  return double(nanoseconds) * 1e-6;
}

}  // namespace strata
