#include "bench_summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace strata::cli {
namespace {

constexpr double kMebibyte = 1024.0 * 1024.0;

}  // namespace

FrameTimeSummary summarise(const std::vector<BenchFrame>& frames) {
  if (frames.empty()) return {};
  std::vector<double> ms;
  for (const BenchFrame& frame : frames) ms.push_back(frame.frameMs);
  std::sort(ms.begin(), ms.end());
  double sum = 0.0;
  for (double value : ms) sum += value;
  const std::size_t n = ms.size();
  const double median = n % 2 == 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
  const std::size_t p95Rank = std::size_t(std::ceil(0.95 * double(n)));
  return {
      .mean = sum / double(n), .median = median, .p95 = ms[std::max<std::size_t>(p95Rank, 1) - 1], .max = ms.back()};
}

std::vector<AveragedPoint> averageFrames(const std::vector<BenchFrame>& frames, int over) {
  std::vector<AveragedPoint> points;
  for (std::size_t first = 0; first < frames.size(); first += std::size_t(over)) {
    const std::size_t last = std::min(frames.size(), first + std::size_t(over));
    AveragedPoint point{.firstFrame = frames[first].frame, .count = int(last - first)};
    for (std::size_t i = first; i < last; ++i) {
      point.frameMs += frames[i].frameMs;
      point.prepareMs += frames[i].prepareMs;
      point.renderMs += frames[i].renderMs;
      point.visibilityMs += frames[i].visibilityMs;
      point.vertices += double(frames[i].vertices);
      point.pagesUploaded += double(frames[i].uploadedThisFrame);
      point.processMiB += double(frames[i].processBytes) / kMebibyte;
      point.gpuMiB += double(frames[i].gpuBytes) / kMebibyte;
      point.openFiles += frames[i].openFiles;
    }
    const double n = point.count;
    point.frameMs /= n, point.prepareMs /= n, point.renderMs /= n, point.visibilityMs /= n;
    point.vertices /= n, point.pagesUploaded /= n;
    point.processMiB /= n, point.gpuMiB /= n, point.openFiles /= n;
    points.push_back(point);
  }
  return points;
}

std::string comparisonReport(const std::string& first, const FrameTimeSummary& a, const std::string& second,
                             const FrameTimeSummary& b) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "frame ms   %12s %12s  ratio (second / first)\n"
                "mean       %12.2f %12.2f  %.3f\n"
                "median     %12.2f %12.2f  %.3f\n"
                "p95        %12.2f %12.2f  %.3f\n"
                "max        %12.2f %12.2f  %.3f\n"
                "first: %s\nsecond: %s\n",
                "first", "second", a.mean, b.mean, b.mean / a.mean, a.median, b.median, b.median / a.median, a.p95,
                b.p95, b.p95 / a.p95, a.max, b.max, b.max / a.max, first.c_str(), second.c_str());
  return text;
}

}  // namespace strata::cli
