#include "bench_csv.hpp"

#include <cstdio>
#include <fstream>
#include <string>

#include <strata/error.hpp>

namespace strata::cli {
namespace {

constexpr const char* kHeader =
    "frame,seconds,altitude_m,frame_ms,prepare_ms,render_ms,visibility_ms,subdivision_ms,rasterisation_ms,patches,"
    "vertices,triangles,pages_resident,pages_wanted,page_faults,pages_uploaded,pages_uploaded_total,gpu_bytes,"
    "process_rss_bytes,open_files";

// One column per node's render pass, gpu_ms_<node id>, in the order the nodes ran.
std::string header(const BenchFrame& first) {
  std::string text = kHeader;
  for (const PassTime& pass : first.passes) text += ",gpu_ms_" + pass.node;
  return text;
}

std::string row(const BenchFrame& f) {
  char text[512];
  std::snprintf(
      text, sizeof text, "%d,%.4f,%.1f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%d,%llu,%llu,%d,%d,%d,%llu,%llu,%llu,%llu,%d",
      f.frame, f.seconds, f.altitude, f.frameMs, f.prepareMs, f.renderMs, f.visibilityMs, f.subdivisionMs,
      f.rasterisationMs, f.patches, static_cast<unsigned long long>(f.vertices),
      static_cast<unsigned long long>(f.triangles), f.pagesResident, f.pagesWanted, f.pageFaults,
      static_cast<unsigned long long>(f.uploadedThisFrame), static_cast<unsigned long long>(f.pagesUploaded),
      static_cast<unsigned long long>(f.gpuBytes), static_cast<unsigned long long>(f.processBytes), f.openFiles);
  std::string line = text;
  for (const PassTime& pass : f.passes) {
    std::snprintf(text, sizeof text, ",%.3f", pass.gpuMs);
    line += text;
  }
  return line;
}

}  // namespace

void writeBenchCsv(const std::filesystem::path& file, const std::vector<BenchFrame>& frames) {
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file);
  out << (frames.empty() ? std::string(kHeader) : header(frames.front())) << '\n';
  for (const BenchFrame& frame : frames) out << row(frame) << '\n';
  if (!out) throw Error(SourceLocation{file.string()}, "cannot write the benchmark's CSV", "give -o a writable path");
}

}  // namespace strata::cli
