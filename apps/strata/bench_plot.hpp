#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "bench_summary.hpp"

namespace strata::cli {

// One pipeline's run, averaged, as the plot draws it.
struct PlotRun {
  std::string name;
  std::vector<AveragedPoint> points;
  int frames = 0;
};

// An SVG like Figs. 5.2 to 5.6 of [Kooima 2008, §5.1]: frame time per averaged point over the run, on
// their scale, 30 Hz (33.3 ms) at the top and 60 Hz at the middle, doubled until the slowest point fits
// (a CPU renderer's frames take far longer); the first run's phases beside it; below, pages uploaded and
// vertices per frame; at the bottom, process and page-cache memory and open files (flat in a soak run once
// the cache is full). Written by hand: no plotting dependency. Throws strata::Error naming the file when it
// cannot be written.
void writeBenchPlot(const std::filesystem::path& file, const std::vector<PlotRun>& runs, int averagedOver);

// The top of the frame time axis: 1000/30 ms, doubled until `slowestMs` fits.
double frameTimeAxisTop(double slowestMs);

}  // namespace strata::cli
