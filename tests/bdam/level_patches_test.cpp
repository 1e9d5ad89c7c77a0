// A level's patches on disk while `strata build-bdam` builds the levels above: what is appended reads back byte for
// byte at the offsets append gave, a patch of no bytes included, and the file is gone when the level is.
#include <gtest/gtest.h>

#include <vector>

#include "level_patches.hpp"
#include "temporary_directory.hpp"

namespace strata::bdam {
namespace {

std::vector<std::byte> bytesFrom(int first, int count) {
  std::vector<std::byte> bytes;
  for (int i = 0; i < count; ++i) bytes.push_back(std::byte((first + 7 * i) & 0xff));
  return bytes;
}

TEST(LevelPatches, ReadBackWhatWasAppendedAndRemoveTheirFile) {
  const test::TemporaryDirectory folder;
  const std::filesystem::path path = folder.path() / "level-3.patches";
  std::vector<std::vector<std::byte>> appended;
  std::vector<std::uint64_t> offsets;
  {
    LevelPatches patches(path);
    for (int p = 0; p < 100; ++p) {
      appended.push_back(bytesFrom(p, (p * 37) % 500));  // 0 to 499 bytes, the first empty
      offsets.push_back(patches.append(appended.back()));
    }
    patches.finish();
    EXPECT_TRUE(std::filesystem::exists(path));
    for (std::size_t p = 0; p < appended.size(); ++p) {
      const std::span<const std::byte> read = patches.at(offsets[p], std::uint32_t(appended[p].size()));
      EXPECT_TRUE(std::equal(read.begin(), read.end(), appended[p].begin(), appended[p].end())) << "patch " << p;
    }
    const auto size = std::filesystem::file_size(path);
    EXPECT_THROW(patches.at(size - 1, 2), std::out_of_range);
    EXPECT_THROW(patches.append(appended[1]), std::logic_error);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(LevelPatches, AFolderThatIsNotThereIsNamed) {
  const test::TemporaryDirectory folder;
  const std::filesystem::path path = folder.path() / "absent" / "level-0.patches";
  try {
    LevelPatches patches(path);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace strata::bdam
