#pragma once
#include <string>

#include <strata/date.hpp>

namespace strata::cli {

// `strata render --dates FIRST/LAST --frames N`: N frames of the scene at dates evenly spaced from FIRST to
// LAST inclusive (ISO 8601 dates, the interval written as ISO 8601 writes one), each to its own file named by
// a pattern such as out/year_%04d.png, so that a time series animates as a frame sequence.
struct DateSweep {
  DayNumber first = 0.0;
  DayNumber last = 0.0;
  int frames = 0;

  DayNumber dateOf(int frame) const { return frames > 1 ? first + (last - first) * frame / (frames - 1) : first; }
};

// Reads "2004-01-01/2004-12-31" with `frames` >= 2; throws strata::Error naming --dates or --frames.
DateSweep parseDateSweep(const std::string& interval, int frames);

// Checks that `pattern` names each frame's file: exactly one %d field (with an optional width, %05d), any other
// % doubled. Throws strata::Error naming -o.
void checkFramePattern(const std::string& pattern);
// The pattern with `frame` in its field.
std::string frameFileName(const std::string& pattern, int frame);

}  // namespace strata::cli
