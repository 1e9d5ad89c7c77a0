#pragma once
// 32-bit words stored as one item of a file's GDAL metadata: little-endian, base64, so that tables of
// ranges (HEALPix page ranges, raster block ranges) travel inside the file `strata tile` writes.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace strata {

std::string base64OfWords(std::span<const std::uint32_t> words);
// The `count` words of `text`; none where it does not hold exactly that many.
std::optional<std::vector<std::uint32_t>> wordsOfBase64(const char* text, std::size_t count);

}  // namespace strata
