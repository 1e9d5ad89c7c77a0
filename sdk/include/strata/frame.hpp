#pragma once
#include <cstdint>

#include <strata/body.hpp>
#include <strata/camera.hpp>

namespace strata {

// What every node sees of the frame being made.
struct FrameState {
  const Body* body = nullptr;
  View view;
  std::uint64_t index = 0;  // frames since the pipeline loaded
};

}  // namespace strata
