#pragma once
#include <array>
#include <filesystem>
#include <memory>

#include <strata/body.hpp>

#include "face_file.hpp"

namespace strata::bdam {

// The six face files `strata build-bdam` wrote in a folder, mapped: what geometry.bdam reads its patches, errors and
// spheres from.
class BdamData {
 public:
  // Throws FaceFileError naming a file that is missing, damaged, or of another build than the others (another
  // radius, leaf level or divisions).
  explicit BdamData(const std::filesystem::path& folder);

  const FaceFile& face(int face) const { return *faces_[std::size_t(face)]; }
  const FaceFile& faceOf(const BintreeNode& node) const { return face(node.root / 2); }
  double radius() const { return face(0).header().radius; }
  int leafLevel() const { return face(0).header().leafLevel; }
  // What every patch keeps within, m above the radius.
  HeightRange heights() const;
  std::uint32_t mostVertices() const;
  std::uint32_t mostIndices() const;

 private:
  std::array<std::unique_ptr<FaceFile>, kCubeFaces> faces_;
};

}  // namespace strata::bdam
