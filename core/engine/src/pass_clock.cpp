#include "pass_clock.hpp"

namespace strata {

PassClock::PassClock(std::size_t passes) : queries_(passes + 1) {
  glCreateQueries(GL_TIMESTAMP, GLsizei(queries_.size()), queries_.data());
}

PassClock::~PassClock() { glDeleteQueries(GLsizei(queries_.size()), queries_.data()); }

void PassClock::mark(std::size_t boundary) {
  glQueryCounter(queries_[boundary], GL_TIMESTAMP);
  marked_ = marked_ || boundary + 1 == queries_.size();
}

std::vector<double> PassClock::milliseconds() const {
  std::vector<double> passes(queries_.size() - 1, 0.0);
  if (!marked_) return passes;
  std::vector<GLuint64> times(queries_.size());
  for (std::size_t i = 0; i < queries_.size(); ++i) glGetQueryObjectui64v(queries_[i], GL_QUERY_RESULT, &times[i]);
  for (std::size_t i = 0; i < passes.size(); ++i)
    passes[i] = times[i + 1] > times[i] ? double(times[i + 1] - times[i]) * 1e-6 : 0.0;
  return passes;
}

}  // namespace strata
