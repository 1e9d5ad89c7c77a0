#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <strata/camera.hpp>
#include <strata/engine.hpp>

#include "test_rasters.hpp"

namespace strata::pgm::test {

using strata::test::Image;

// Renders the pipeline loaded in `engine` from `camera` for `frames` frames (the first settles what it
// can: renderComplete) and reads back the last.
Image renderFrames(Engine& engine, const Camera& camera, int width, int height, int frames);

// Whether a pixel of an output.image frame shows the body: its background is black.
bool covered(const Image& image, int x, int y);

}  // namespace strata::pgm::test
