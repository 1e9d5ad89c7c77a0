#include "settled_frame.hpp"

#include <cstdio>
#include <utility>
#include <vector>

namespace strata::cli {
namespace {

// Enough for a tree allowed 64 operations a frame to refine from a view of the whole planet to a metre.
constexpr int kMostRenders = 256;

}  // namespace

const FrameOutput& renderSettled(Engine& engine, int width, int height) {
  const FrameOutput* frame = &engine.renderComplete(width, height);
  std::vector<unsigned char> before = readPixels(frame->frame());
  for (int render = 1; render < kMostRenders; ++render) {
    frame = &engine.renderComplete(width, height);
    std::vector<unsigned char> after = readPixels(frame->frame());
    if (after == before) return *frame;
    before = std::move(after);
  }
  std::fprintf(stderr, "strata: warning: frame %llu still changed after %d renders; it may differ between runs\n",
               static_cast<unsigned long long>(engine.statistics().frame), kMostRenders);
  return *frame;
}

}  // namespace strata::cli
