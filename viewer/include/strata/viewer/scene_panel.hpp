#pragma once
#include <string>

#include <strata/host/engine.hpp>

namespace strata::viewer {

// The viewer's scene panel (issue 9): the scene's date as a slider a year either side of the pipeline's
// (time series follow it in the next frame, composite.temporal_blend), shown where the pipeline gives a
// `date:`; in a scene of several bodies, which body the camera is placed over; and the last frame's statistics: its
// phases' times, the geometry's patches and vertices, and the page cache's occupancy, loads and failures. Call it
// between PanelOverlay::begin() and end().
void drawScenePanel(Engine& engine);

// `camera` placed over the body `id`, of shape `to`, from over `from`: at the same longitude, latitude, heading
// and tilt, and as far from the new body's centre, in its radii, as it was from the old one's, so that the new
// body fills as much of the frame as the old one did.
Camera cameraOverBody(const Camera& camera, const Body& from, const Body& to, const std::string& id);

}  // namespace strata::viewer
