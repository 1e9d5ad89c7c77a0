#pragma once
#include <yaml-cpp/yaml.h>

#include <strata/host/camera_path.hpp>

#include "pipeline/source_map.hpp"

// The two forms a path file's body takes (docs/camera-paths.md), each checked with the pipeline loader's
// located errors: every field's type, range and presence, unknown keys with a did-you-mean.
namespace strata::paths {

// `keyframes: [{time: 0, lon: 0, lat: 20, altitude: 2.0e7}, ...]`
CameraPath readKeyframes(const YAML::Node& list, const loader::SourceMap& source);
// `fly_to: {from: {lon: 0, lat: 20, altitude: 2.0e7}, to: {...}, duration: 20}`
CameraPath readFlyTo(const YAML::Node& map, const loader::SourceMap& source, const Body& body);

}  // namespace strata::paths
