#pragma once
#include <strata/host/engine.hpp>

namespace strata::viewer {

// The viewer's scene panel (issue 9): the scene's date as a slider a year either side of the pipeline's
// (time series follow it in the next frame, composite.temporal_blend), shown where the pipeline gives a
// `date:`; and the last frame's statistics: its phases' times, the geometry's patches and vertices, and the
// page cache's occupancy, loads and failures. Call it between PanelOverlay::begin() and end().
void drawScenePanel(Engine& engine);

}  // namespace strata::viewer
