#pragma once
#include <string>
#include <vector>

#include "bench_frames.hpp"

namespace strata::cli {

// The frame times of a benchmark run in a few numbers (ms).
struct FrameTimeSummary {
  double mean = 0.0;
  double median = 0.0;
  double p95 = 0.0;  // 95th percentile, nearest rank
  double max = 0.0;
};

FrameTimeSummary summarise(const std::vector<BenchFrame>& frames);

// One point of the plot: the mean of `count` successive frames, as [Kooima 2008, §5.1] averaged its
// 4800 frames over 10 into 480 points.
struct AveragedPoint {
  int firstFrame = 0;
  int count = 0;
  double frameMs = 0.0, prepareMs = 0.0, renderMs = 0.0, visibilityMs = 0.0;
  double vertices = 0.0;
  double pagesUploaded = 0.0;  // per frame
  double processMiB = 0.0;     // resident set
  double gpuMiB = 0.0;         // the page cache's GPU memory
  double openFiles = 0.0;
};

std::vector<AveragedPoint> averageFrames(const std::vector<BenchFrame>& frames, int over);

// Two pipelines' runs on one path (--compare): each one's summary and the second's over the first's.
// Returns the lines printed and written.
std::string comparisonReport(const std::string& first, const FrameTimeSummary& a, const std::string& second,
                             const FrameTimeSummary& b);

}  // namespace strata::cli
