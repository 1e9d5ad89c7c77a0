#include "pgm_scenes.hpp"

#include <strata/output.hpp>

namespace strata::pgm::test {

Image renderFrames(Engine& engine, const Camera& camera, int width, int height, int frames) {
  engine.camera() = camera;
  const FrameOutput* output = &engine.renderComplete(width, height);
  for (int frame = 1; frame < frames; ++frame) output = &engine.render(width, height);
  return Image{width, height, readPixels(output->frame())};
}

bool covered(const Image& image, int x, int y) {
  const std::array<int, 4> pixel = image.at(x, y);
  return pixel[0] + pixel[1] + pixel[2] > 0;
}

}  // namespace strata::pgm::test
