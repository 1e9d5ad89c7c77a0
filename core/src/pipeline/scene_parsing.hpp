#pragma once
#include <filesystem>

#include <yaml-cpp/yaml.h>

#include <strata/body.hpp>
#include <strata/camera.hpp>
#include <strata/colour_settings.hpp>
#include <strata/page_cache_settings.hpp>

#include "pipeline/source_map.hpp"

// The `body:` and `camera:` sections of a pipeline. Both are optional maps, and so is every key in them:
// what is absent keeps the defaults of body.hpp and camera.hpp.
namespace strata::loader {

// body: {name: Earth, radius: 6371000}. name is text; radius is a number of metres > 0.
Body parseBody(const YAML::Node& map, const SourceMap& source);

// camera: {lon, lat, altitude, heading, tilt, fov}, all numbers:
//   lon: degrees, any value, wrapped into [-180, 180)     lat: degrees in [-90, 90]
//   altitude: metres above the body's radius, > 0        heading: degrees, any value, kept as given
//   tilt: degrees in [0, 90] (0 looks straight down)      fov: vertical, degrees in [0.001, 179]
Camera parseCamera(const YAML::Node& map, const SourceMap& source);

// cache: {budget, uploads_per_frame, loader_threads}, whole numbers (PageCacheSettings):
//   budget: MiB of GPU memory for pages, upload staging included, in [16, 1048576]
//   uploads_per_frame: pages copied to the GPU per frame, in [1, 256]
//   loader_threads: threads reading pages, in [1, 64]
PageCacheSettings parseCache(const YAML::Node& map, const SourceMap& source);

// colour: {config: FILE}: an OpenColorIO config (docs/colour.md), relative to `directory`; it must exist.
ColourSettings parseColour(const YAML::Node& map, const SourceMap& source, const std::filesystem::path& directory);

}  // namespace strata::loader
