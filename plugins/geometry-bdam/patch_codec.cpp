#include "patch_codec.hpp"

#include <zstd.h>

#include <cstdint>
#include <limits>
#include <string>

namespace strata::bdam {
namespace {

constexpr int kZstdLevel = 3;                     // zstd's default: fast to read, as the paper chose LZO for
constexpr std::size_t kLargestPatch = 64u << 20;  // bytes before compression: a patch holds a few hundred triangles

std::uint64_t zigzag(std::int64_t value) { return (std::uint64_t(value) << 1) ^ std::uint64_t(value >> 63); }
std::int64_t unzigzag(std::uint64_t value) { return std::int64_t(value >> 1) ^ -std::int64_t(value & 1); }

void putVarint(std::vector<std::byte>& out, std::uint64_t value) {
  for (; value >= 0x80; value >>= 7) out.push_back(std::byte(0x80 | (value & 0x7f)));
  out.push_back(std::byte(value));
}

// Reads the varints of a decompressed patch, each checked to lie within the bytes and within 64 bits.
class VarintReader {
 public:
  explicit VarintReader(std::span<const std::byte> bytes) : bytes_(bytes) {}
  std::uint64_t next() {
    std::uint64_t value = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (at_ == bytes_.size()) throw PatchFormatError("the patch ends inside a number");
      const auto byte = std::uint64_t(bytes_[at_++]);
      value |= (byte & 0x7f) << shift;
      if (!(byte & 0x80)) return value;
    }
    throw PatchFormatError("a number of the patch runs past 64 bits");
  }
  // A difference of at most `bound` either way, so that adding it to what it differs from cannot overflow.
  std::int64_t nextDifference(std::int64_t bound) {
    const std::int64_t difference = unzigzag(next());
    if (difference < -bound || difference > bound) throw PatchFormatError("a difference of the patch is out of range");
    return difference;
  }
  std::size_t left() const { return bytes_.size() - at_; }

 private:
  std::span<const std::byte> bytes_;
  std::size_t at_ = 0;
};

std::vector<std::byte> compress(const std::vector<std::byte>& raw) {
  std::vector<std::byte> out(ZSTD_compressBound(raw.size()));
  ZSTD_CCtx* context = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(context, ZSTD_c_compressionLevel, kZstdLevel);
  ZSTD_CCtx_setParameter(context, ZSTD_c_checksumFlag, 1);
  const std::size_t size = ZSTD_compress2(context, out.data(), out.size(), raw.data(), raw.size());
  ZSTD_freeCCtx(context);
  if (ZSTD_isError(size))
    throw std::runtime_error(std::string("zstd could not compress a patch: ") + ZSTD_getErrorName(size));
  out.resize(size);
  out.shrink_to_fit();  // the builder holds every patch stored: the bound is 2 to 3 times what is used
  return out;
}

std::vector<std::byte> decompress(std::span<const std::byte> bytes) {
  if (ZSTD_findFrameCompressedSize(bytes.data(), bytes.size()) != bytes.size())
    throw PatchFormatError("the patch is not one whole zstd frame (truncated, or followed by other bytes)");
  const unsigned long long size = ZSTD_getFrameContentSize(bytes.data(), bytes.size());
  if (size == ZSTD_CONTENTSIZE_ERROR || size == ZSTD_CONTENTSIZE_UNKNOWN || size > kLargestPatch)
    throw PatchFormatError("the patch's zstd frame gives no size, or one over " + std::to_string(kLargestPatch) +
                           " bytes");
  std::vector<std::byte> raw(size);
  const std::size_t read = ZSTD_decompress(raw.data(), raw.size(), bytes.data(), bytes.size());
  if (ZSTD_isError(read))
    throw PatchFormatError(std::string("the patch does not decompress: ") + ZSTD_getErrorName(read));
  if (read != size) throw PatchFormatError("the patch decompresses to fewer bytes than its frame says");
  return raw;
}

DisplacedVertex nextVertex(VarintReader& reader, const DisplacedVertex& before) {
  const std::int64_t b1 = before.b1 + reader.nextDifference(kBarycentricSteps);
  const std::int64_t b2 = before.b2 + reader.nextDifference(kBarycentricSteps);
  const std::int64_t centimetres = before.centimetres + reader.nextDifference(std::int64_t(1) << 32);
  if (b1 < 0 || b2 < 0 || b1 + b2 > kBarycentricSteps) throw PatchFormatError("a vertex lies outside its triangle");
  if (centimetres < std::numeric_limits<std::int32_t>::min() || centimetres > std::numeric_limits<std::int32_t>::max())
    throw PatchFormatError("a displacement is out of range");
  return {std::uint16_t(b1), std::uint16_t(b2), std::int32_t(centimetres)};
}

}  // namespace

std::vector<std::byte> encodePatch(const DisplacedPatch& patch) {
  checkPatch(patch);
  std::vector<std::byte> raw;
  putVarint(raw, patch.vertices.size());
  putVarint(raw, patch.indices.size());
  DisplacedVertex before;
  for (const DisplacedVertex& vertex : patch.vertices) {
    putVarint(raw, zigzag(std::int64_t(vertex.b1) - before.b1));
    putVarint(raw, zigzag(std::int64_t(vertex.b2) - before.b2));
    putVarint(raw, zigzag(std::int64_t(vertex.centimetres) - before.centimetres));
    before = vertex;
  }
  std::int64_t previous = 0;
  for (const std::uint32_t index : patch.indices) {
    putVarint(raw, zigzag(std::int64_t(index) - previous));
    previous = index;
  }
  return compress(raw);
}

DisplacedPatch decodePatch(std::span<const std::byte> bytes) {
  const std::vector<std::byte> raw = decompress(bytes);
  VarintReader reader(raw);
  const std::uint64_t vertices = reader.next(), indices = reader.next();
  if (vertices > reader.left() / 3 || indices > reader.left())  // a vertex takes at least 3 bytes, an index 1
    throw PatchFormatError("the patch counts more vertices or indices than its bytes hold");
  DisplacedPatch patch;
  patch.vertices.reserve(vertices);
  for (DisplacedVertex before; patch.vertices.size() < vertices; before = patch.vertices.back())
    patch.vertices.push_back(nextVertex(reader, before));
  patch.indices.reserve(indices);
  for (std::int64_t index = 0; patch.indices.size() < indices;) {
    index += reader.nextDifference(std::int64_t(vertices));
    if (index < 0 || std::uint64_t(index) >= vertices) throw PatchFormatError("an index names no vertex of the patch");
    patch.indices.push_back(std::uint32_t(index));
  }
  if (indices % 3 != 0) throw PatchFormatError("the patch's indices are not whole triangles");
  if (reader.left() != 0) throw PatchFormatError("the patch has bytes after its last index");
  return patch;
}

}  // namespace strata::bdam
