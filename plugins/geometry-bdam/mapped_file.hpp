#pragma once
#include <cstddef>
#include <filesystem>
#include <span>

namespace strata::bdam {

// A whole file mapped read-only [Cignoni et al. 2003, §4.4: "each terrain partition is a file dynamically mapped into a
// read-only logical address space"], unmapped when this goes; an empty file maps to no bytes. The face files and the
// build's level files read through it.
class MappedFile {
 public:
  MappedFile() = default;
  // Throws std::runtime_error naming the file and why it could not be mapped.
  explicit MappedFile(const std::filesystem::path& path);
  ~MappedFile();
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;

  std::span<const std::byte> bytes() const { return {static_cast<const std::byte*>(mapping_), size_}; }
  // madvise(2) over the pages that hold `part` (bytes of this file): MADV_RANDOM, MADV_WILLNEED, ...
  void advise(std::span<const std::byte> part, int advice) const;

 private:
  void* mapping_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace strata::bdam
