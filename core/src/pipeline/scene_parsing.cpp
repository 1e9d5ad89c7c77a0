#include "pipeline/scene_parsing.hpp"

#include <array>
#include <cmath>

#include "pipeline/camera_fields.hpp"
#include "pipeline/interval.hpp"
#include "pipeline/value_reading.hpp"
#include "pipeline/yaml_maps.hpp"

namespace strata::loader {
namespace {

std::vector<std::string> cameraKeys() {
  std::vector<std::string> keys;
  for (const auto& field : kCameraFields) keys.emplace_back(field.name);
  return keys;
}

// From a boulder to beyond the Sun (6.96e8 m). Far larger, heights and footprints the GPU takes in float
// relative to the radius lose their digits: a body of 1e14 m was drawn speckled, of 1e20 m grey.
const Interval kBodyRadius = Interval::closed(1.0, 1.0e9);

// Longitudes name the same meridian modulo 360; one range keeps later arithmetic simple.
double wrapLongitude(double lon) {
  const double wrapped = std::fmod(lon + 180.0, 360.0);
  return (wrapped < 0.0 ? wrapped + 360.0 : wrapped) - 180.0;
}

void requireMap(const YAML::Node& map, const SourceMap& source, const std::string& section,
                const std::string& example) {
  if (!map.IsMap())
    throw source.error(map, {}, "'" + section + "' must be a map, got " + describe(map), "write it as " + example);
  requireUniqueKeys(map, source, "key");
}

// The `cache:` keys: a whole number each, within what a machine can use.
struct CacheField {
  const char* name;
  Interval allowed;
  const char* units;
  void (*apply)(PageCacheSettings&, std::int64_t);
};

const std::array<CacheField, 3> kCacheFields{{
    // 16 MiB hold the upload staging and a few pages of each format.
    {"budget", Interval::closed(16.0, 1 << 20), "MiB",
     [](PageCacheSettings& cache, std::int64_t mib) { cache.budgetBytes = std::uint64_t(mib) << 20; }},
    {"uploads_per_frame", Interval::closed(1.0, 256.0), "pages",
     [](PageCacheSettings& cache, std::int64_t pages) { cache.uploadsPerFrame = int(pages); }},
    {"loader_threads", Interval::closed(1.0, 64.0), "threads",
     [](PageCacheSettings& cache, std::int64_t threads) { cache.loaderThreads = int(threads); }},
}};

}  // namespace

Body parseBody(const YAML::Node& map, const SourceMap& source) {
  requireMap(map, source, "body", "body: {name: Earth, radius: 6371000}");
  requireKnownKeys(map, {"name", "radius"}, source, "body");
  Body body;
  if (const YAML::Node name = map["name"]) body.name = readText(name, {source, "body 'name'", {}});
  if (const YAML::Node radius = map["radius"]) {
    const ValueContext context{source, "body 'radius'", {}};
    body.radius = readReal(radius, context);
    requireWithin(body.radius, kBodyRadius, "m", radius, context);
  }
  return body;
}

Camera parseCamera(const YAML::Node& map, const SourceMap& source) {
  requireMap(map, source, "camera", "camera: {lon: 10, lat: 20, altitude: 2.0e7}");
  requireKnownKeys(map, cameraKeys(), source, "camera");
  Camera camera;
  for (const auto& field : kCameraFields) {
    const YAML::Node value = map[field.name];
    if (!value) continue;
    const ValueContext context{source, std::string("camera '") + field.name + "'", {}};
    const double number = readReal(value, context);
    requireWithin(number, field.allowed, field.units, value, context);
    camera.*field.member = number;
  }
  camera.lon = wrapLongitude(camera.lon);
  return camera;
}

PageCacheSettings parseCache(const YAML::Node& map, const SourceMap& source) {
  requireMap(map, source, "cache", "cache: {budget: 256}");
  std::vector<std::string> keys;
  for (const auto& field : kCacheFields) keys.emplace_back(field.name);
  requireKnownKeys(map, keys, source, "cache");
  PageCacheSettings cache;
  cache.where = source.at(map);
  for (const auto& field : kCacheFields) {
    const YAML::Node value = map[field.name];
    if (!value) continue;
    const ValueContext context{source, std::string("cache '") + field.name + "'", {}};
    const std::int64_t number = readInteger(value, context);
    requireWithin(double(number), field.allowed, field.units, value, context);
    field.apply(cache, number);
  }
  return cache;
}

ColourSettings parseColour(const YAML::Node& map, const SourceMap& source, const std::filesystem::path& directory) {
  requireMap(map, source, "colour", "colour: {config: my.ocio}");
  requireKnownKeys(map, {"config"}, source, "colour");
  ColourSettings colour;
  const YAML::Node value = map["config"];
  if (!value) return colour;
  const ValueContext context{source, "colour 'config'", {}};
  colour.config = (directory / readText(value, context)).lexically_normal();
  colour.where = source.at(value);
  std::error_code error;
  if (!std::filesystem::is_regular_file(colour.config, error))
    throw source.error(value, {}, "colour 'config': file not found: " + colour.config.string(),
                       "give the path of an OpenColorIO config (.ocio), relative to the pipeline's directory " +
                           directory.string() + ", or leave `colour:` out for $OCIO's or Strata's own");
  return colour;
}

}  // namespace strata::loader
