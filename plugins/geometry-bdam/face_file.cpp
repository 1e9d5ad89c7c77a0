#include "face_file.hpp"

#include <sys/mman.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <vector>

#include "patch_codec.hpp"

namespace strata::bdam {
namespace {

static_assert(std::endian::native == std::endian::little, "face files are read and written as the host lays them");

constexpr std::array<char, 16> kMagic = {'S', 'T', 'R', 'A', 'T', 'A', '-', 'B',
                                         'D', 'A', 'M', '-', 'F', 'A', 'C', 'E'};

#pragma pack(push, 1)
struct StoredHeader {
  std::array<char, 16> magic;
  std::uint32_t version, face, leafLevel, divisions;
  double radius, lowest, highest;
  std::uint64_t nodesPerBintree, patchesFrom;
  std::uint32_t mostVertices, mostIndices, crc, unused;
};
struct StoredRecord {
  std::uint64_t offset;
  std::uint32_t bytes, crc;
  double error, centre[3], radius;
};
#pragma pack(pop)
static_assert(sizeof(StoredHeader) == 88 && sizeof(StoredRecord) == 56);

template <typename T>
std::uint32_t crcOf(T value, std::uint32_t T::*field) {  // with the CRC's own field zero
  value.*field = 0;
  return std::uint32_t(crc32(0, reinterpret_cast<const Bytef*>(&value), sizeof(T)));
}

std::uint64_t nodesPerBintree(int leafLevel) { return (std::uint64_t(2) << leafLevel) - 1; }
std::uint64_t slotOf(const BintreeNode& node, int leafLevel) {
  return std::uint64_t(node.root % 2) * nodesPerBintree(leafLevel) + (std::uint64_t(1) << node.level) - 1 + node.path;
}

template <typename T>
T readAt(std::span<const std::byte> bytes, std::uint64_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

// Face `face`'s nodes in the table's order: bintree 0's, then 1's, each level after the one above, by path.
std::vector<BintreeNode> nodesOfFace(int face, int leafLevel) {
  std::vector<BintreeNode> order;
  for (int half = 0; half < 2; ++half)
    for (int level = 0; level <= leafLevel; ++level)
      for (std::uint64_t p = 0; p < (std::uint64_t(1) << level); ++p) order.push_back({2 * face + half, level, p});
  return order;
}

}  // namespace

void writeFaceFile(const std::filesystem::path& path, int face, const BuiltBintrees& bintrees) {
  const int leafLevel = bintrees.leafLevel();
  const auto divisions = std::uint32_t(bintrees.options().divisions);
  const double radius = bintrees.options().radius;
  const std::vector<BintreeNode> order = nodesOfFace(face, leafLevel);
  double lowest = std::numeric_limits<double>::max(), highest = -lowest;
  std::uint32_t mostVertices = 0, mostIndices = 0;
  for (const BintreeNode& node : order) {
    const BuiltNode& built = bintrees.at(node);
    lowest = std::min(lowest, built.lowest), highest = std::max(highest, built.highest);
    mostVertices = std::max(mostVertices, built.vertices), mostIndices = std::max(mostIndices, built.indices);
  }
  const std::uint64_t nodes = nodesPerBintree(leafLevel);
  StoredHeader stored{kMagic,
                      kFaceFileVersion,
                      std::uint32_t(face),
                      std::uint32_t(leafLevel),
                      divisions,
                      radius,
                      lowest,
                      highest,
                      nodes,
                      sizeof(StoredHeader) + 2 * nodes * sizeof(StoredRecord),
                      mostVertices,
                      mostIndices,
                      0,
                      0};
  stored.crc = crcOf(stored, &StoredHeader::crc);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(&stored), sizeof stored);
  std::uint64_t offset = stored.patchesFrom;
  for (const BintreeNode& node : order) {
    const BuiltNode& built = bintrees.at(node);
    StoredRecord record{offset,
                        built.bytes,
                        0,
                        built.error,
                        {built.sphere.centre.x, built.sphere.centre.y, built.sphere.centre.z},
                        built.sphere.radius};
    record.crc = crcOf(record, &StoredRecord::crc);
    out.write(reinterpret_cast<const char*>(&record), sizeof record);
    offset += built.bytes;
  }
  for (const BintreeNode& node : order) {
    const std::span<const std::byte> patch = bintrees.stored(node);
    out.write(reinterpret_cast<const char*>(patch.data()), std::streamsize(patch.size()));
  }
  out.close();
  if (!out) throw FaceFileError(path.string() + ": cannot be written: " + std::strerror(errno));
}

FaceFile::FaceFile(const std::filesystem::path& path) : path_(path) {
  try {
    mapped_ = MappedFile(path);
  } catch (const std::runtime_error& error) {
    throw FaceFileError(error.what());
  }
  if (bytes().size() < sizeof(StoredHeader))
    throw FaceFileError(path.string() + ": is not a face file of `strata build-bdam` (too short, or unreadable)");
  // Read what is asked for and no more: the kernel's read-around would fetch neighbours that no view asked for, and
  // the patches a flight will want are asked for ahead by prefetch().
  mapped_.advise(bytes(), MADV_RANDOM);
  const auto stored = readAt<StoredHeader>(bytes(), 0);
  const auto refuse = [&](const std::string& what) { return FaceFileError(path.string() + ": " + what); };
  if (stored.magic != kMagic) throw refuse("is not a face file of `strata build-bdam`");
  if (stored.version != kFaceFileVersion)
    throw refuse("is a face file of format " + std::to_string(stored.version) + ", this Strata reads format " +
                 std::to_string(kFaceFileVersion) + ": build it again with this `strata build-bdam`");
  if (stored.crc != crcOf(stored, &StoredHeader::crc) || stored.face >= kCubeFaces || stored.leafLevel > 30 ||
      stored.divisions == 0 || !(stored.radius > 0.0) || !std::isfinite(stored.radius) ||
      !(stored.lowest <= stored.highest) || !std::isfinite(stored.lowest) || !std::isfinite(stored.highest) ||
      stored.nodesPerBintree != nodesPerBintree(int(stored.leafLevel)) ||
      stored.patchesFrom != sizeof(StoredHeader) + 2 * stored.nodesPerBintree * sizeof(StoredRecord) ||
      stored.patchesFrom > bytes().size() || stored.mostIndices % 3 != 0)
    throw refuse("its header is damaged (or the file is cut short): build it again with `strata build-bdam`");
  header_ = {int(stored.face), int(stored.leafLevel), int(stored.divisions), stored.radius,
             stored.lowest,    stored.highest,        stored.mostVertices,   stored.mostIndices};
  nodesPerBintree_ = stored.nodesPerBintree;
  patchesFrom_ = stored.patchesFrom;
}

std::string FaceFile::where(const BintreeNode& node) const {
  return path_.string() + ": bintree " + std::to_string(node.root) + ", level " + std::to_string(node.level) +
         ", node " + std::to_string(node.path);
}

NodeRecord FaceFile::node(const BintreeNode& node) const {
  if (node.root / 2 != header_.face || node.level < 0 || node.level > header_.leafLevel ||
      node.path >= (std::uint64_t(1) << node.level))
    throw std::invalid_argument(where(node) + ": not a node of this face's bintrees");
  const auto record =
      readAt<StoredRecord>(bytes(), sizeof(StoredHeader) + slotOf(node, header_.leafLevel) * sizeof(StoredRecord));
  const bool finite =
      std::isfinite(record.error) && std::isfinite(record.radius) &&
      std::all_of(std::begin(record.centre), std::end(record.centre), [](double v) { return std::isfinite(v); });
  if (record.crc != crcOf(record, &StoredRecord::crc) || !finite || record.error < 0.0 || record.radius < 0.0 ||
      record.offset < patchesFrom_ || record.offset > bytes().size() || record.bytes > bytes().size() - record.offset)
    throw FaceFileError(where(node) + ": its record is damaged, or the file is cut short");
  return {bytes().subspan(record.offset, record.bytes),
          record.error,
          {{record.centre[0], record.centre[1], record.centre[2]}, record.radius}};
}

DisplacedPatch FaceFile::patch(const BintreeNode& node) const {
  const NodeRecord record = this->node(node);
  try {
    return decodePatch(record.stored);
  } catch (const PatchFormatError& error) {
    throw FaceFileError(where(node) + ": its patch is damaged: " + error.what());
  }
}

void FaceFile::prefetch(const BintreeNode& node) const { mapped_.advise(this->node(node).stored, MADV_WILLNEED); }

}  // namespace strata::bdam
