// The library speaks to its host through one sink (strata/log.hpp), never to stderr itself: a warning
// source.gdal gives about a real file reaches the sink a host installs, from the node's open() on the
// engine's workers, and nothing of it reaches stderr; without a sink, the default prints the message and
// its fix there.
#include <gtest/gtest.h>

#include <mutex>
#include <string>
#include <vector>

#include <strata/log.hpp>

#include "rendering.hpp"
#include "temporary_directory.hpp"

namespace strata::test {
namespace {

// Collects what the library logs while it lives, then gives the sink back.
class CollectedLog {
 public:
  CollectedLog()
      : previous_(setLogSink([this](const LogMessage& message) {
          std::lock_guard lock(lock_);
          messages_.push_back(message);
        })) {}
  ~CollectedLog() { setLogSink(previous_); }

  std::vector<LogMessage> messages() const {
    std::lock_guard lock(lock_);
    return messages_;
  }

 private:
  mutable std::mutex lock_;
  std::vector<LogMessage> messages_;
  LogSink previous_;
};

std::string globePipeline(const std::filesystem::path& imagery) {
  return "strata: 1\n"
         "body: {name: Earth, radius: 6371000}\n"
         "camera: {lon: 137.4, lat: -4.6, altitude: 2.0e7, fov: 45}\n"
         "nodes:\n"
         "  imagery: {type: source.gdal, path: '" +
         imagery.string() +
         "', kind: color}\n"
         "  terrain: {type: geometry.icosahedral}\n"
         "  frame: {type: output.image, geometry: terrain, surface: [imagery]}\n";
}

// A raster wider than 4096 texels without overviews: source.gdal warns that its coarse pages are slow.
TEST(HostLog, ASourcesWarningReachesTheHostsSinkAndNotStderr) {
  TemporaryDirectory directory;
  const std::filesystem::path imagery = directory.path() / "flat.tif";
  writeColourRaster(imagery, 4100, 2050, {-180.0, -90.0, 180.0, 90.0}, [](int, int) { return Rgb8{90, 120, 60}; });
  const std::filesystem::path pipeline = directory.write("globe.yaml", globePipeline(imagery));

  CollectedLog log;
  testing::internal::CaptureStderr();
  std::unique_ptr<Engine> engine = makeEngine();
  renderFrame(*engine, pipeline, 64, 32);
  const std::string printed = testing::internal::GetCapturedStderr();

  std::vector<LogMessage> messages;  // of this file: a driver may log its own messages meanwhile
  for (const LogMessage& message : log.messages())
    if (message.text.find("flat.tif") != std::string::npos) messages.push_back(message);
  ASSERT_EQ(messages.size(), 1u) << printed;
  EXPECT_EQ(messages[0].level, LogLevel::Warning);
  EXPECT_NE(messages[0].text.find("flat.tif' (4100x2050) has no overviews"), std::string::npos) << messages[0].text;
  EXPECT_NE(messages[0].fix.find("strata tile"), std::string::npos) << messages[0].fix;
  EXPECT_EQ(printed.find("overviews"), std::string::npos) << printed;
}

// What the library logged about `file` while rendering `pipeline` once.
std::vector<LogMessage> messagesAbout(const std::filesystem::path& pipeline, const std::string& file) {
  CollectedLog log;
  std::unique_ptr<Engine> engine = makeEngine();
  renderFrame(*engine, pipeline, 64, 32);
  std::vector<LogMessage> messages;
  for (const LogMessage& message : log.messages())
    if (message.text.find(file) != std::string::npos) messages.push_back(message);
  return messages;
}

// A global map of Mars (the IAU 2000 sphere of 3396190 m) given to a pipeline of the Earth is reported at its
// source, naming both bodies, and drawn; on Mars it is not reported.
TEST(HostLog, ARasterOfAnotherBodyIsReported) {
  TemporaryDirectory directory;
  const std::filesystem::path mars = directory.path() / "mars.tif";
  writeRasterFile(mars, {.crs = "+proj=longlat +R=3396190 +no_defs",
                         .geotransform = {-180.0, 0.6, 0.0, 90.0, 0.0, -0.6},
                         .bands = 3,
                         .type = GDT_Byte,
                         .nodata = std::nullopt});
  std::string pipeline = globePipeline(mars);
  const std::vector<LogMessage> onEarth = messagesAbout(directory.write("earth.yaml", pipeline), "mars.tif");
  ASSERT_EQ(onEarth.size(), 1u);
  EXPECT_NE(onEarth[0].text.find("lies on a body of 3396190 m (Mars's), not on the pipeline's Earth of 6371000 m"),
            std::string::npos)
      << onEarth[0].text;
  EXPECT_NE(onEarth[0].text.find("earth.yaml:5:"), std::string::npos) << onEarth[0].text;
  EXPECT_NE(onEarth[0].fix.find("body: {name: Mars}"), std::string::npos) << onEarth[0].fix;
  pipeline.replace(pipeline.find("{name: Earth, radius: 6371000}"), 30, "{name: Mars}");
  EXPECT_TRUE(messagesAbout(directory.write("mars.yaml", pipeline), "mars.tif").empty());
}

TEST(HostLog, WithoutASinkAMessageAndItsFixArePrintedToStderr) {
  testing::internal::CaptureStderr();
  logWarning("the page cache holds 12 of 40 pages", "give the cache a larger budget");
  logMessage({LogLevel::Info, "loaded", {}});
  EXPECT_EQ(testing::internal::GetCapturedStderr(),
            "strata: warning: the page cache holds 12 of 40 pages\n  fix: give the cache a larger budget\n"
            "strata: info: loaded\n");
}

}  // namespace
}  // namespace strata::test
