#include "path_sections.hpp"

#include <array>
#include <sstream>

#include "pipeline/interval.hpp"
#include "pipeline/scene_parsing.hpp"
#include "pipeline/value_reading.hpp"
#include "pipeline/yaml_maps.hpp"
#include "sphere_geodesics.hpp"

namespace strata::paths {
namespace {

using loader::Interval;
using loader::SourceMap;

// Where the camera is must be said; how it looks defaults to Camera's (north up, straight down).
std::vector<std::string> requiredCameraKeys() {
  const ParameterBindings<Camera>& camera = cameraParameters();
  return {camera.declarationOf(&Camera::lon).name, camera.declarationOf(&Camera::lat).name,
          camera.declarationOf(&Camera::altitude).name};
}

constexpr const char* kCameraExample = "{lon: 10, lat: 46, altitude: 5000}";

void requireMap(const YAML::Node& map, const SourceMap& source, const std::string& what, const std::string& example) {
  if (!map.IsMap())
    throw source.error(map, {}, what + " must be a map, got " + loader::describe(map), "write it as " + example);
  loader::requireUniqueKeys(map, source, "key");
}

// A number the map must have, within `allowed`.
double readField(const YAML::Node& map, const char* key, const Interval& allowed, const char* units,
                 const SourceMap& source, const std::string& what) {
  const YAML::Node value = map[key];
  if (!value)
    throw source.error(map, {}, what + " has no '" + key + "'",
                       std::string("add `") + key + ": ...` (" + allowed.str(units) + ")");
  const loader::ValueContext context{source, what + " '" + key + "'", {}};
  const double number = loader::readReal(value, context);
  loader::requireWithin(number, allowed, units, value, context);
  return number;
}

// A camera map: `what` names it ("keyframe 2"); `extraKeys` are the other keys it may have.
Camera readCamera(const YAML::Node& map, const SourceMap& source, const std::string& what,
                  std::vector<std::string> extraKeys) {
  requireMap(map, source, what, kCameraExample);
  const std::vector<ParameterDeclaration>& parameters = cameraParameters().declarations();
  for (const std::string& name : loader::namesOf(parameters)) extraKeys.push_back(name);
  loader::requireKnownKeys(map, extraKeys, source, what);
  for (const std::string& key : requiredCameraKeys())
    if (!map[key])
      throw source.error(map, {}, what + " has no '" + key + "'", "add `" + key + ": ...` to place the camera");
  return loader::cameraOf(loader::parseDeclared(map, parameters, what, source, {}));
}

bool antipodalCameras(const Camera& a, const Camera& b) {
  return antipodal(unitVectorDegrees(a.lon, a.lat), unitVectorDegrees(b.lon, b.lat));
}

std::string seconds(double time) {
  std::ostringstream text;
  text << time << " s";
  return text.str();
}

void requireLater(const CameraKeyframe& keyframe, const CameraKeyframe& before, const YAML::Node& map,
                  const SourceMap& source, const std::string& what) {
  if (keyframe.time > before.time) return;
  throw source.error(map["time"], {},
                     what + "'s time, " + seconds(keyframe.time) + ", is not later than the keyframe before's, " +
                         seconds(before.time),
                     "list the keyframes in increasing time, each later than the one before");
}

}  // namespace

CameraPath readKeyframes(const YAML::Node& list, const SourceMap& source) {
  const std::string example =
      "write `keyframes:` and under it lines such as `- {time: 0, lon: 0, lat: 20, altitude: 2.0e7}`";
  if (!list.IsSequence())
    throw source.error(list, {}, "'keyframes' must be a list of cameras, got " + loader::describe(list), example);
  if (list.size() < 2)
    throw source.error(list, {}, "'keyframes' has " + std::to_string(list.size()) + "; a path needs at least two",
                       example);
  std::vector<CameraKeyframe> keyframes;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node map = list[k];
    const std::string what = "keyframe " + std::to_string(k + 1);
    CameraKeyframe keyframe{0.0, readCamera(map, source, what, {"time"})};
    keyframe.time = readField(map, "time", Interval::any(), "s", source, what);
    if (k > 0) {
      requireLater(keyframe, keyframes.back(), map, source, what);
      if (antipodalCameras(keyframes.back().camera, keyframe.camera))
        throw source.error(map, {}, what + " is antipodal to the keyframe before: no one great circle joins them",
                           "add a keyframe between them on the way round you mean");
    }
    keyframes.push_back(keyframe);
  }
  return CameraPath::throughKeyframes(std::move(keyframes));
}

CameraPath readFlyTo(const YAML::Node& map, const SourceMap& source, const Body& body) {
  requireMap(map, source, "'fly_to'", "fly_to: {from: " + std::string(kCameraExample) + ", to: {...}, duration: 20}");
  loader::requireKnownKeys(map, {"from", "to", "duration", "rho"}, source, "'fly_to'");
  CameraFlight flight;
  for (const char* end : {"from", "to"})
    if (!map[end])
      throw source.error(map, {}, std::string("'fly_to' has no '") + end + "' camera",
                         std::string("add `") + end + ": " + kCameraExample + "`");
  flight.from = readCamera(map["from"], source, "'fly_to' 'from'", {});
  flight.to = readCamera(map["to"], source, "'fly_to' 'to'", {});
  flight.duration = readField(map, "duration", Interval::above(0.0), "s", source, "'fly_to'");
  if (map["rho"]) flight.rho = readField(map, "rho", Interval::above(0.0), "", source, "'fly_to'");
  if (antipodalCameras(flight.from, flight.to))
    throw source.error(map["to"], {}, "'fly_to' goes between antipodal points: no one great circle joins them",
                       "use `keyframes:` with a keyframe between them on the way round you mean");
  return CameraPath::flight(flight, body);
}

}  // namespace strata::paths
