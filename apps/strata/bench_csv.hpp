#pragma once
#include <filesystem>
#include <vector>

#include "bench_frames.hpp"

namespace strata::cli {

// Writes one row per frame under a header row whose names carry their units (frame_ms, gpu_bytes, ...);
// docs/benchmarks.md says what each column means. Makes the directory; throws strata::Error naming the
// file when it cannot be written.
void writeBenchCsv(const std::filesystem::path& file, const std::vector<BenchFrame>& frames);

}  // namespace strata::cli
