#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <span>

#include "mapped_file.hpp"

namespace strata::bdam {

// One bintree level's stored patches while the build goes on above it [Cignoni et al. 2003, §5: the construction runs
// out of core]: appended to a file in the build's scratch folder as they are made, so that memory holds a few thousand
// patches rather than a planet's, and mapped read-only once the level is whole, for the level above to simplify and
// for the face files to copy. The file is removed when this is destroyed.
class LevelPatches {
 public:
  explicit LevelPatches(std::filesystem::path path);  // creates the file; throws std::runtime_error naming it
  ~LevelPatches();
  LevelPatches(const LevelPatches&) = delete;
  LevelPatches& operator=(const LevelPatches&) = delete;

  // Appends a patch's bytes and returns where they start; until finish().
  std::uint64_t append(std::span<const std::byte> patch);
  // Closes the file and maps it; throws std::runtime_error naming it if it could not be written whole.
  void finish();
  // Bytes appended earlier, once finished.
  std::span<const std::byte> at(std::uint64_t offset, std::uint32_t size) const;

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::uint64_t size_ = 0;
  MappedFile mapped_;
};

}  // namespace strata::bdam
