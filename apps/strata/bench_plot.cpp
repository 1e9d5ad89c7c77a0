#include "bench_plot.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

#include <strata/error.hpp>

namespace strata::cli {
namespace {

constexpr double kWidth = 960, kHeight = 830;
constexpr double kLeft = 80, kRight = 880;               // the panels' x extent
constexpr double kTimeTop = 80, kTimeBottom = 380;       // frame time panel; legends and title above
constexpr double kDataTop = 450, kDataBottom = 600;      // pages and vertices panel
constexpr double kMemoryTop = 640, kMemoryBottom = 780;  // memory and open files panel
constexpr const char* kRunColours[] = {"#000000", "#d62728"};
constexpr const char* kPhaseColours[] = {"#1f77b4", "#2ca02c", "#ff7f0e"};

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f", value);
  return text;
}

// A pipeline's file name as SVG text: the XML's special characters escaped.
std::string escaped(const std::string& words) {
  std::string result;
  for (char c : words) {
    switch (c) {
      case '&': result += "&amp;"; break;
      case '<': result += "&lt;"; break;
      case '>': result += "&gt;"; break;
      default: result += c;
    }
  }
  return result;
}

double xOf(int frame, int frames) { return kLeft + (kRight - kLeft) * double(frame) / double(std::max(frames - 1, 1)); }

// A polyline of one quantity of the averaged points, scaled so that `top` is at `yTop`.
std::string polyline(const PlotRun& run, const std::function<double(const AveragedPoint&)>& value, double top,
                     double yTop, double yBottom, const std::string& style) {
  std::ostringstream points;
  for (const AveragedPoint& point : run.points) {
    const double y = yBottom - (yBottom - yTop) * std::min(value(point) / top, 1.0);
    points << number(xOf(point.firstFrame + point.count / 2, run.frames)) << ',' << number(y) << ' ';
  }
  return "<polyline fill=\"none\" " + style + " points=\"" + points.str() + "\"/>\n";
}

std::string text(double x, double y, const std::string& words, const std::string& extra = {}) {
  return "<text x=\"" + number(x) + "\" y=\"" + number(y) + "\" " + extra + ">" + words + "</text>\n";
}

std::string gridLine(double y) {
  return "<line x1=\"" + number(kLeft) + "\" y1=\"" + number(y) + "\" x2=\"" + number(kRight) + "\" y2=\"" + number(y) +
         "\" stroke=\"#cccccc\"/>\n";
}

// Gridlines at the top, middle and bottom of the frame time axis, labelled in ms and Hz.
std::string frameTimeAxis(double top) {
  std::string svg;
  for (double fraction : {1.0, 0.5, 0.25}) {
    const double y = kTimeBottom - (kTimeBottom - kTimeTop) * fraction, ms = top * fraction;
    svg += gridLine(y) + text(kLeft - 6, y + 4, number(ms) + " ms", "text-anchor=\"end\"") +
           text(kRight + 6, y + 4, number(1000.0 / ms) + " Hz");
  }
  svg += gridLine(kTimeBottom);
  return svg + text(20, (kTimeTop + kTimeBottom) / 2, "frame time",
                    "transform=\"rotate(-90 20 " + number((kTimeTop + kTimeBottom) / 2) + ")\" text-anchor=\"middle\"");
}

std::string frameTimePanel(const std::vector<PlotRun>& runs, double top) {
  std::string svg = "<g id=\"frame-time\">\n" + frameTimeAxis(top);
  const PlotRun& first = runs.front();
  const std::function<double(const AveragedPoint&)> phases[] = {[](const AveragedPoint& p) { return p.prepareMs; },
                                                                [](const AveragedPoint& p) { return p.renderMs; },
                                                                [](const AveragedPoint& p) { return p.visibilityMs; }};
  const char* phaseNames[] = {"prepare (CPU)", "render (CPU, submit)", "visibility (CPU)"};
  for (int i = 0; i < 3; ++i) {
    svg += polyline(first, phases[i], top, kTimeTop, kTimeBottom,
                    std::string("stroke=\"") + kPhaseColours[i] + "\" stroke-width=\"1\"");
    svg += text(kLeft + 10 + 170 * i, kTimeTop - 10, phaseNames[i], std::string("fill=\"") + kPhaseColours[i] + "\"");
  }
  for (std::size_t r = 0; r < runs.size() && r < 2; ++r) {
    svg += polyline(
        runs[r], [](const AveragedPoint& p) { return p.frameMs; }, top, kTimeTop, kTimeBottom,
        std::string("stroke=\"") + kRunColours[r] + "\" stroke-width=\"2\"");
    svg += text(kLeft + 10, kTimeTop - 26 - 16 * double(r), "frame: " + escaped(runs[r].name),
                std::string("fill=\"") + kRunColours[r] + "\"");
  }
  return svg + "</g>\n";
}

// Pages uploaded per frame and vertices, each scaled to its own largest value over the first run.
std::string dataPanel(const PlotRun& run) {
  double pages = 1.0, vertices = 1.0;
  for (const AveragedPoint& p : run.points)
    pages = std::max(pages, p.pagesUploaded), vertices = std::max(vertices, p.vertices);
  std::string svg = "<g id=\"pages-and-vertices\">\n" + gridLine(kDataTop) + gridLine(kDataBottom);
  svg += polyline(
      run, [](const AveragedPoint& p) { return p.pagesUploaded; }, pages, kDataTop, kDataBottom,
      "stroke=\"#9467bd\" stroke-width=\"1.5\"");
  svg += polyline(
      run, [](const AveragedPoint& p) { return p.vertices; }, vertices, kDataTop, kDataBottom,
      "stroke=\"#8c564b\" stroke-width=\"1.5\"");
  svg += text(kLeft - 6, kDataTop + 4, number(pages), "text-anchor=\"end\" fill=\"#9467bd\"");
  svg += text(kRight + 6, kDataTop + 4, number(vertices / 1000.0) + "k", "fill=\"#8c564b\"");
  svg += text(kLeft + 10, kDataTop - 8, "pages uploaded per frame", "fill=\"#9467bd\"");
  svg += text(kLeft + 250, kDataTop - 8, "vertices", "fill=\"#8c564b\"");
  return svg + "</g>\n";
}

// The process's resident set and the page cache's GPU memory on one axis from 0 MiB, and open files on
// their own from 0: in a soak run all three must level off once the cache is full.
std::string memoryPanel(const PlotRun& run) {
  double mebibytes = 1.0, files = 1.0;
  for (const AveragedPoint& p : run.points)
    mebibytes = std::max({mebibytes, p.processMiB, p.gpuMiB}), files = std::max(files, p.openFiles);
  std::string svg = "<g id=\"memory\">\n" + gridLine(kMemoryTop) + gridLine(kMemoryBottom);
  svg += polyline(
      run, [](const AveragedPoint& p) { return p.processMiB; }, mebibytes, kMemoryTop, kMemoryBottom,
      "stroke=\"#17becf\" stroke-width=\"1.5\"");
  svg += polyline(
      run, [](const AveragedPoint& p) { return p.gpuMiB; }, mebibytes, kMemoryTop, kMemoryBottom,
      "stroke=\"#e377c2\" stroke-width=\"1.5\"");
  svg += polyline(
      run, [](const AveragedPoint& p) { return p.openFiles; }, files, kMemoryTop, kMemoryBottom,
      "stroke=\"#7f7f7f\" stroke-width=\"1.5\" stroke-dasharray=\"4 2\"");
  svg += text(kLeft - 6, kMemoryTop + 4, number(mebibytes) + " MiB", "text-anchor=\"end\"");
  svg += text(kLeft - 6, kMemoryBottom + 4, "0", "text-anchor=\"end\"");
  svg += text(kRight + 6, kMemoryTop + 4, number(files) + " files", "fill=\"#7f7f7f\"");
  svg += text(kLeft + 10, kMemoryTop - 8, "process resident set", "fill=\"#17becf\"");
  svg += text(kLeft + 190, kMemoryTop - 8, "page cache GPU memory", "fill=\"#e377c2\"");
  svg += text(kLeft + 380, kMemoryTop - 8, "open files", "fill=\"#7f7f7f\"");
  return svg + "</g>\n";
}

std::string frameAxis(int frames) {
  std::string svg;
  for (int i = 0; i <= 4; ++i) {
    const int frame = (frames - 1) * i / 4;
    svg += text(xOf(frame, frames), kMemoryBottom + 18, std::to_string(frame), "text-anchor=\"middle\"");
  }
  return svg + text((kLeft + kRight) / 2, kMemoryBottom + 40, "frame", "text-anchor=\"middle\"");
}

}  // namespace

double frameTimeAxisTop(double slowestMs) {
  double top = 1000.0 / 30.0;
  while (top < slowestMs) top *= 2.0;
  return top;
}

void writeBenchPlot(const std::filesystem::path& file, const std::vector<PlotRun>& runs, int averagedOver) {
  double slowest = 0.0;
  for (const PlotRun& run : runs)
    for (const AveragedPoint& point : run.points) slowest = std::max(slowest, point.frameMs);
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << text(kLeft, 18,
              "strata bench: " + std::to_string(runs.front().frames) + " frames, averaged over " +
                  std::to_string(averagedOver),
              "font-size=\"14\"")
      << frameTimePanel(runs, frameTimeAxisTop(slowest)) << dataPanel(runs.front()) << memoryPanel(runs.front())
      << frameAxis(runs.front().frames) << "</svg>\n";
  if (!out)
    throw Error(SourceLocation{file.string()}, "cannot write the benchmark's plot", "give --plot a writable path");
}

}  // namespace strata::cli
