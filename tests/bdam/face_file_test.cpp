// geometry.bdam's face files: what `strata build-bdam` writes is what a face file reads back, every node's patch, error
// and sphere, exactly; and a damaged file (any byte of its header, a record, a patch, a file cut short, a file of
// something else) says which file and which node, never a crash or a wrong patch.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

#include "bintree_builder.hpp"
#include "face_file.hpp"
#include "patch_codec.hpp"
#include "raster_heights.hpp"
#include "temporary_directory.hpp"

namespace strata::bdam {
namespace {

constexpr double kMars = 3396190.0;  // m
constexpr int kLeafLevel = 4;
constexpr int kFace = 4;  // +z: the north pole's

const BuiltBintrees& built() {
  static const test::TemporaryDirectory scratch;
  static const BuiltBintrees bintrees = [] {
    const RasterHeights geoid("/usr/share/proj/egm96_15.gtx");
    return buildBintrees([&geoid] { return geoid.sampler(); }, {kMars, kLeafLevel, 16, 2, scratch.path()},
                         [](const LevelReport&) {});
  }();
  return bintrees;
}

std::vector<BintreeNode> faceNodes() {
  std::vector<BintreeNode> nodes;
  for (int root = 2 * kFace; root < 2 * kFace + 2; ++root)
    for (int level = 0; level <= kLeafLevel; ++level)
      for (std::uint64_t p = 0; p < (std::uint64_t(1) << level); ++p) nodes.push_back({root, level, p});
  return nodes;
}

class FaceFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = std::filesystem::path(::testing::TempDir()) / "face-4.bdam";
    writeFaceFile(path_, kFace, built());
    std::ifstream in(path_, std::ios::binary);
    bytes_.assign(std::istreambuf_iterator<char>(in), {});
  }
  void TearDown() override { std::filesystem::remove(path_); }
  // The file with byte `at` changed (or cut to `at` bytes), written back.
  void damage(std::size_t at, bool cut = false) const {
    std::string damaged = bytes_;
    if (cut)
      damaged.resize(at);
    else
      damaged[at] = char(damaged[at] ^ 0x5a);
    std::ofstream(path_, std::ios::binary | std::ios::trunc).write(damaged.data(), std::streamsize(damaged.size()));
  }
  std::filesystem::path path_;
  std::string bytes_;
};

TEST_F(FaceFileTest, ReadsBackEveryNodeExactly) {
  const FaceFile file(path_);
  EXPECT_EQ(file.header().face, kFace);
  EXPECT_EQ(file.header().leafLevel, kLeafLevel);
  EXPECT_EQ(file.header().radius, kMars);
  EXPECT_LT(file.header().lowest, -90.0);  // EGM96 reaches -107 m and +85 m; the triangles' planes dip lower
  EXPECT_GT(file.header().highest, 10.0);
  std::uint32_t mostVertices = 0, mostIndices = 0;
  for (const BintreeNode& node : faceNodes()) {
    const DisplacedPatch patch = file.patch(node);
    mostVertices = std::max(mostVertices, std::uint32_t(patch.vertices.size()));
    mostIndices = std::max(mostIndices, std::uint32_t(patch.indices.size()));
  }
  EXPECT_EQ(file.header().mostVertices, mostVertices);
  EXPECT_EQ(file.header().mostIndices, mostIndices);
  for (const BintreeNode& node : faceNodes()) {
    const NodeRecord record = file.node(node);
    const BuiltNode& original = built().at(node);
    const std::span<const std::byte> stored = built().stored(node);
    ASSERT_TRUE(std::equal(record.stored.begin(), record.stored.end(), stored.begin(), stored.end()));
    EXPECT_EQ(record.error, original.error);
    EXPECT_EQ(record.sphere.centre, original.sphere.centre);
    EXPECT_EQ(record.sphere.radius, original.sphere.radius);
    EXPECT_EQ(file.patch(node), decodePatch(stored));
    file.prefetch(node);
  }
  EXPECT_THROW(file.node({0, 0, 0}), std::invalid_argument);  // another face's
}

TEST_F(FaceFileTest, EveryByteOfTheHeaderIsChecked) {
  for (std::size_t at = 0; at < 88; ++at) {
    damage(at);
    EXPECT_THROW(FaceFile{path_}, FaceFileError) << "byte " << at;
  }
  damage(70, true);
  EXPECT_THROW(FaceFile{path_}, FaceFileError);
}

// What the generator needs to draw a coarser patch instead: the damage named, the rest of the file still readable.
TEST_F(FaceFileTest, ADamagedRecordOrPatchNamesTheFileAndTheNode) {
  const BintreeNode node{2 * kFace + 1, 3, 5}, parent{2 * kFace + 1, 2, 2};
  const std::size_t record = 88 + 56 * ((std::size_t(2) << kLeafLevel) - 1 + 7 + 5);
  const auto message = [&](auto read) {
    try {
      read(FaceFile(path_));
    } catch (const FaceFileError& error) {
      return std::string(error.what());
    }
    return std::string("nothing was wrong");
  };
  damage(record + 20);  // its error
  EXPECT_EQ(message([&](const FaceFile& f) { f.node(node); }),
            path_.string() + ": bintree 9, level 3, node 5: its record is damaged, or the file is cut short");
  EXPECT_EQ(message([&](const FaceFile& f) { f.patch(parent); }), "nothing was wrong");

  std::uint64_t offset = 0;
  std::memcpy(&offset, bytes_.data() + record, sizeof offset);
  damage(offset + 5);
  EXPECT_NE(message([&](const FaceFile& f) { f.patch(node); }).find("bintree 9, level 3, node 5: its patch is damaged"),
            std::string::npos);
  EXPECT_EQ(message([&](const FaceFile& f) { f.patch(parent); }), "nothing was wrong");

  damage(offset + 5, true);  // cut short inside the patch
  EXPECT_NE(message([&](const FaceFile& f) { f.patch(node); }).find("or the file is cut short"), std::string::npos);
  EXPECT_EQ(message([&](const FaceFile& f) { f.patch(parent); }), "nothing was wrong");
}

TEST(FaceFile, AFileOfSomethingElseIsNotAFaceFile) {
  try {
    FaceFile file("/usr/share/proj/egm96_15.gtx");
    ADD_FAILURE() << "read a geoid as a face file";
  } catch (const FaceFileError& error) {
    EXPECT_EQ(std::string(error.what()), "/usr/share/proj/egm96_15.gtx: is not a face file of `strata build-bdam`");
  }
}

}  // namespace
}  // namespace strata::bdam
