#include "foundation/metadata_words.hpp"

#include <cpl_conv.h>
#include <cpl_string.h>

namespace strata {

std::string base64OfWords(std::span<const std::uint32_t> words) {
  std::vector<GByte> bytes;
  bytes.reserve(words.size() * 4);
  for (const std::uint32_t word : words)
    for (int shift = 0; shift < 32; shift += 8) bytes.push_back(GByte(word >> shift));
  char* text = CPLBase64Encode(int(bytes.size()), bytes.data());
  std::string result(text);
  CPLFree(text);
  return result;
}

std::optional<std::vector<std::uint32_t>> wordsOfBase64(const char* text, std::size_t count) {
  std::string buffer(text);
  const int length = CPLBase64DecodeInPlace(reinterpret_cast<GByte*>(buffer.data()));
  if (length < 0 || std::size_t(length) != count * 4) return std::nullopt;
  std::vector<std::uint32_t> words(count);
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 3; k >= 0; --k) words[i] = words[i] << 8 | std::uint8_t(buffer[4 * i + std::size_t(k)]);
  return words;
}

}  // namespace strata
