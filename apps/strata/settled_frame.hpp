#pragma once
#include <strata/engine.hpp>

namespace strata::cli {

// The frame of a sequence whose camera moves, rendered until it no longer changes: every page it wants is
// loaded (Engine::renderComplete), and the geometry has caught up with the camera. A generator makes a
// bounded number of splits and merges a frame (geometry.icosahedral's `operations`), so after the camera
// jumps from one frame of a sequence to the next it takes several frames to refine, and how many of them
// renderComplete happened to draw while pages loaded would otherwise show in the result. Rendered until two
// frames in a row are identical, a sequence is the same on every run.
const FrameOutput& renderSettled(Engine& engine, int width, int height);

}  // namespace strata::cli
