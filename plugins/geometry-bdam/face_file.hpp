#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>

#include "bintree_builder.hpp"
#include "displaced_patch.hpp"
#include "mapped_file.hpp"

namespace strata::bdam {

// One cube face's two bintrees as a file [Cignoni et al. 2003, §4.4: "each terrain partition is a file dynamically
// mapped into a read-only logical address space"; §3: pointerless trees], little-endian:
//   a header of 88 bytes: "STRATA-BDAM-FACE", the format's version, the face, the leaf level, the leaves' divisions,
//     the body's radius, the lowest and highest its patches reach (f64, m), the nodes a bintree has, the offset of
//     the first patch, the most vertices and indices a patch has, and the CRC-32 of all that;
//   a table of 56-byte records, bintree 0's nodes then bintree 1's, each level after the one above it and a level's
//     nodes by path (node 2^level - 1 + path): its patch's offset and size, its error, its sphere's centre and radius
//     (f64, m), and the CRC-32 of the record;
//   the patches (patch_codec.hpp), in the table's order, coarse first, so that a flight's first reads lie together.
// Every part is checked where it is read, so that damage shows as a FaceFileError naming the file and the node.
inline constexpr std::uint32_t kFaceFileVersion = 1;

struct FaceFileHeader {
  int face = 0;
  int leafLevel = 0;
  int divisions = 0;
  double radius = 0.0;
  double lowest = 0.0, highest = 0.0;               // m above the radius: what every patch of the face keeps within
  std::uint32_t mostVertices = 0, mostIndices = 0;  // of a patch of the face
};

// Writes face `face` of `bintrees` to `path`.
void writeFaceFile(const std::filesystem::path& path, int face, const BuiltBintrees& bintrees);

class FaceFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct NodeRecord {
  std::span<const std::byte> stored;  // the patch's bytes, in the mapped file
  double error = 0.0;
  BoundingSphere sphere;
};

// A face file mapped read-only: its header checked when opened, each record and patch when read.
class FaceFile {
 public:
  explicit FaceFile(const std::filesystem::path& path);  // throws FaceFileError

  const FaceFileHeader& header() const { return header_; }
  // A node of one of this face's two bintrees, to the leaf level; throws FaceFileError for a damaged record.
  NodeRecord node(const BintreeNode& node) const;
  // Its patch decoded; throws FaceFileError for a damaged one.
  DisplacedPatch patch(const BintreeNode& node) const;
  // Asks the kernel to read the node's patch ahead, without waiting (the paper's madvise prefetch, §4.4).
  void prefetch(const BintreeNode& node) const;

 private:
  std::span<const std::byte> bytes() const { return mapped_.bytes(); }
  std::string where(const BintreeNode& node) const;

  std::filesystem::path path_;
  MappedFile mapped_;
  FaceFileHeader header_;
  std::uint64_t nodesPerBintree_ = 0;
  std::uint64_t patchesFrom_ = 0;
};

}  // namespace strata::bdam
