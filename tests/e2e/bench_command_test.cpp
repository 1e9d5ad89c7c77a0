// `strata bench`: a short run along a path writes a CSV row per frame with sane values and an SVG plot;
// --compare prints the ratios of two pipelines' frame times; mistakes are refused with a fix.
#include <gtest/gtest.h>

#include <cpl_minixml.h>

#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "strata_command.hpp"

namespace {

namespace fs = std::filesystem;

using strata::test::CommandResult;
using strata::test::contains;
using strata::test::readText;
using strata::test::StrataCommandTest;

constexpr int kFrames = 12;

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  for (std::string field; std::getline(stream, field, ',');) fields.push_back(field);
  return fields;
}

// The CSV's rows, each a map from the header's column names to the row's numbers.
std::vector<std::map<std::string, double>> readCsv(const fs::path& file) {
  std::stringstream text(readText(file));
  std::string line;
  std::getline(text, line);
  const std::vector<std::string> header = split(line);
  std::vector<std::map<std::string, double>> rows;
  while (std::getline(text, line)) {
    const std::vector<std::string> fields = split(line);
    EXPECT_EQ(fields.size(), header.size()) << line;
    std::map<std::string, double> row;
    for (std::size_t i = 0; i < fields.size() && i < header.size(); ++i) row[header[i]] = std::stod(fields[i]);
    rows.push_back(row);
  }
  return rows;
}

int countElements(const CPLXMLNode* node, const std::string& name) {
  int count = 0;
  for (; node != nullptr; node = node->psNext) {
    if (node->eType != CXT_Element) continue;
    count += (name == node->pszValue) + countElements(node->psChild, name);
  }
  return count;
}

TEST_F(StrataCommandTest, BenchWritesARowPerFrameAndAPlot) {
  const CommandResult result = run({"bench", "pipelines/bench-flyin.yaml", "--frames", std::to_string(kFrames),
                                    "--size", "96x54", "--average", "4", "-o", file("bench/flyin.csv").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "frame ms mean")) << result.out;
  const auto rows = readCsv(file("bench/flyin.csv"));
  ASSERT_EQ(rows.size(), std::size_t(kFrames));
  for (int frame = 0; frame < kFrames; ++frame) {
    const auto& row = rows[std::size_t(frame)];
    EXPECT_EQ(row.at("frame"), frame);
    EXPECT_GT(row.at("frame_ms"), 0.0) << frame;
    EXPECT_GT(row.at("prepare_ms"), 0.0) << frame;
    EXPECT_GT(row.at("vertices"), 0.0) << frame;
    EXPECT_GT(row.at("process_rss_bytes"), 1.0e6) << frame;
    EXPECT_GT(row.at("gpu_bytes"), 0.0) << frame;
    EXPECT_GE(row.at("open_files"), 3.0) << "stdin, stdout and stderr at least: " << frame;
    double passes = 0.0;  // each node's GPU time, a column per node of the pipeline
    for (const char* node : {"global", "strip", "laid", "relief", "terrain", "frame"}) {
      EXPECT_GE(row.at(std::string("gpu_ms_") + node), 0.0) << node << ", frame " << frame;
      passes += row.at(std::string("gpu_ms_") + node);
    }
    EXPECT_GT(passes, 0.0) << frame;
    if (frame > 0) {
      EXPECT_GT(row.at("seconds"), rows[std::size_t(frame - 1)].at("seconds"));
      EXPECT_GE(row.at("pages_uploaded_total"), rows[std::size_t(frame - 1)].at("pages_uploaded_total"));
    }
  }
  // The path goes down and back: it ends where it starts, 20,000 km up, and comes close to the ground between.
  EXPECT_NEAR(rows.front().at("altitude_m"), 2.0e7, 1.0);
  EXPECT_NEAR(rows.back().at("altitude_m"), 2.0e7, 1.0);
  EXPECT_LT(rows[kFrames / 2].at("altitude_m"), 1.0e6);
  EXPECT_GT(rows.back().at("pages_uploaded_total"), 0.0) << "the colours are paged";

  CPLXMLNode* svg = CPLParseXMLString(readText(file("bench/flyin.svg")).c_str());
  ASSERT_NE(svg, nullptr) << "the plot is not XML";
  EXPECT_NE(CPLSearchXMLNode(svg, "=svg"), nullptr);
  EXPECT_EQ(countElements(svg, "polyline"), 9);  // frame time, three phases, pages, vertices, memory, files
  EXPECT_GE(countElements(svg, "text"), 10);
  CPLDestroyXMLNode(svg);
  EXPECT_TRUE(contains(readText(file("bench/flyin.svg")), " Hz<")) << "the frame time axis is labelled in Hz";
}

TEST_F(StrataCommandTest, BenchComparesTwoPipelinesOnOnePath) {
  const CommandResult result =
      run({"bench", "pipelines/procedural.yaml", "--path", "pipelines/paths/flyin.yaml", "--compare",
           "pipelines/pgm.yaml", "--frames", "4", "--size", "64x36", "-o", file("a.csv").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  EXPECT_TRUE(contains(result.out, "ratio (second / first)")) << result.out;
  EXPECT_TRUE(contains(result.out, "second: pipelines/pgm.yaml")) << result.out;
  EXPECT_EQ(readCsv(file("a.csv")).size(), 4u);
  EXPECT_EQ(readCsv(file("a_compare.csv")).size(), 4u);
  EXPECT_TRUE(contains(readText(file("a_compare.txt")), "median")) << "the comparison is written too";
  CPLXMLNode* svg = CPLParseXMLString(readText(file("a.svg")).c_str());
  ASSERT_NE(svg, nullptr);
  EXPECT_EQ(countElements(svg, "polyline"), 10);  // a frame time line for each pipeline
  CPLDestroyXMLNode(svg);
}

// A soak run flies the path lap after lap: each lap starts where the path does, 20,000 km up.
TEST_F(StrataCommandTest, BenchFliesThePathLapAfterLap) {
  const CommandResult result = run({"bench", "pipelines/bench-flyin.yaml", "--frames", "12", "--laps", "3", "--size",
                                    "48x27", "-o", file("soak.csv").string()});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  const auto rows = readCsv(file("soak.csv"));
  ASSERT_EQ(rows.size(), 12u);
  for (const std::size_t lap : {0u, 4u, 8u}) EXPECT_NEAR(rows[lap].at("altitude_m"), 2.0e7, 1.0) << lap;
  EXPECT_LT(rows[2].at("altitude_m"), 1.0e6);
  const CommandResult refused = run({"bench", "pipelines/bench-flyin.yaml", "--frames", "12", "--laps", "7"});
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_TRUE(contains(refused.err, "--laps: error")) << refused.err;
}

TEST_F(StrataCommandTest, BenchRefusesAMissingPathAndBadNumbers) {
  const CommandResult missing = run({"bench", "pipelines/procedural.yaml", "--path", file("none.yaml").string()});
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_TRUE(contains(missing.err, file("none.yaml").string() + ": error: no camera path file here")) << missing.err;
  EXPECT_TRUE(contains(missing.err, "fix:")) << missing.err;
  const CommandResult pipeline = run({"bench", "none.yaml"});
  EXPECT_EQ(pipeline.exitCode, 1);
  EXPECT_TRUE(contains(pipeline.err, "none.yaml: error: pipeline file not found")) << pipeline.err;
  const CommandResult implicit = run({"bench", "pipelines/procedural.yaml"});
  EXPECT_EQ(implicit.exitCode, 1);
  EXPECT_TRUE(contains(implicit.err, "pipelines/paths/procedural.yaml")) << implicit.err;
  EXPECT_TRUE(contains(implicit.err, "give --path FILE")) << implicit.err;
  const CommandResult size = run({"bench", "pipelines/bench-flyin.yaml", "--size", "0x54"});
  EXPECT_EQ(size.exitCode, 1);
  EXPECT_TRUE(contains(size.err, "--size")) << size.err;
  const CommandResult frames = run({"bench", "pipelines/bench-flyin.yaml", "--frames", "1"});
  EXPECT_EQ(frames.exitCode, 1);
  EXPECT_TRUE(contains(frames.err, "--frames: error: a benchmark takes at least 2 frames")) << frames.err;
}

}  // namespace
