#include "sample_scene.hpp"

#include <string>
#include <vector>

namespace explorer {
namespace {

using Ids = std::vector<std::string>;

// Two procedural patterns stand in for a monthly series of dust cover, blended by the scene's date; a
// mission would read its maps with composite.temporal_blend's `files:` instead.
void addDust(strata::PipelineBuilder& scene) {
  for (const auto& [id, seed] : {std::pair{"dust-winter", 7}, std::pair{"dust-summer", 11}})
    scene.node(id, "source.procedural",
               {{"kind", "color"}, {"seed", seed}, {"wavelength", 6.0e6}, {"contour_interval", 20000}});
  scene.node("dust", "composite.temporal_blend",
             {{"steps", Ids{"dust-winter", "dust-summer"}},
              {"dates", Ids{"2030-01-15", "2030-07-15"}},
              {"repeat", "yearly"}});  // July blends back into January
}

}  // namespace

strata::PipelineBuilder sampleScene() {
  strata::PipelineBuilder scene("mars-explorer sample scene");
  scene.set("body.name", "Mars").set("body.radius", 3396190.0);                     // m; the mean radius of Mars
  scene.set("camera.lon", 30).set("camera.lat", 25).set("camera.altitude", 8.0e6);  // the whole disc
  scene.set("date", "2030-04-15");  // between the dust series' two steps
  scene.node("colours", "source.procedural", {{"kind", "color"}, {"seed", 2008}});  // a height ramp with contours
  scene.node("heights", "source.procedural", {{"kind", "height"}, {"seed", 2008}});
  // The colours shaded from the north-west; slopes of a few percent, steepened to read from orbit.
  scene.node("terrain", "composite.relief", {{"height", "heights"}, {"surface", "colours"}, {"exaggeration", 20}});
  addDust(scene);
  scene.node("globe", "geometry.icosahedral");
  scene.node("frame", "output.image", {{"geometry", "globe"}, {"surface", Ids{"terrain", "dust"}}});
  return scene;
}

}  // namespace explorer
