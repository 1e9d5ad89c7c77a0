#include "level_patches.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace strata::bdam {

LevelPatches::LevelPatches(std::filesystem::path path)
    : path_(std::move(path)), out_(path_, std::ios::binary | std::ios::trunc) {
  if (!out_) throw std::runtime_error(path_.string() + ": cannot be written: " + std::strerror(errno));
}

LevelPatches::~LevelPatches() {
  mapped_ = {};
  out_.close();
  std::error_code ignored;  // a scratch folder removed first (on an interruption) took the file with it
  std::filesystem::remove(path_, ignored);
}

std::uint64_t LevelPatches::append(std::span<const std::byte> patch) {
  if (!out_.is_open()) throw std::logic_error(path_.string() + ": appended to after it was finished");
  out_.write(reinterpret_cast<const char*>(patch.data()), std::streamsize(patch.size()));
  const std::uint64_t offset = size_;
  size_ += patch.size();
  return offset;
}

void LevelPatches::finish() {
  out_.close();
  if (!out_) throw std::runtime_error(path_.string() + ": cannot be written: " + std::strerror(errno));
  mapped_ = MappedFile(path_);
}

std::span<const std::byte> LevelPatches::at(std::uint64_t offset, std::uint32_t size) const {
  const std::span<const std::byte> bytes = mapped_.bytes();
  if (offset > bytes.size() || size > bytes.size() - offset)
    throw std::out_of_range(path_.string() + ": no patch at byte " + std::to_string(offset));
  return bytes.subspan(offset, size);
}

}  // namespace strata::bdam
