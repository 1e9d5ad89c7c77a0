#pragma once
#include <cstdint>
#include <optional>
#include <strata/export.hpp>

#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/date.hpp>
#include <strata/sun.hpp>

STRATA_EXPORTS_BEGIN
namespace strata {

// What every node sees of the frame being made.
struct FrameState {
  const Body* body = nullptr;
  View view;
  std::uint64_t index = 0;        // frames since the pipeline loaded
  std::optional<DayNumber> date;  // the scene's date (Engine::date()); none where the pipeline gives none
  // Where the sun stands overhead: the pipeline's `sun:`, else the date's for the Earth (sceneSun), and in a
  // scene of several bodies the scene's sun as the body sees it, in its axes; none where neither is known.
  std::optional<SubsolarPoint> sun;
  // A frame drawn to be kept (Engine::renderSettled): generators whose detail follows a moving view over
  // several frames settle it at once, as they do on a pipeline's first frame, whatever that costs.
  bool still = false;
  // The view half a second on, the eye moved on as it moved since the last frame (cameraAhead): what the page cache
  // and geometry.bdam read ahead for [Cignoni et al. 2003, §4.4]. None on a still frame, when the camera has not
  // moved, and on a pipeline's first frame.
  std::optional<View> ahead;
  // The frame is laid over other bodies' (a scene's `bodies:`, docs/pipelines.md) with premultiplied alpha:
  // outputs give a pixel the share of it the body covers in alpha and their colour times that share, leave it
  // transparent where no surface shows (alpha 0), and may add light there (a body's air glowing beyond its limb).
  bool transparentBackground = false;
};

}  // namespace strata
STRATA_EXPORTS_END
