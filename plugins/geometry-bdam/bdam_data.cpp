#include "bdam_data.hpp"

#include <algorithm>
#include <string>

namespace strata::bdam {

BdamData::BdamData(const std::filesystem::path& folder) {
  for (int f = 0; f < kCubeFaces; ++f) {
    const std::filesystem::path path = folder / ("face-" + std::to_string(f) + ".bdam");
    faces_[std::size_t(f)] = std::make_unique<FaceFile>(path);
    const FaceFileHeader& header = faces_[std::size_t(f)]->header();
    const FaceFileHeader& first = faces_[0]->header();
    if (header.face != f)
      throw FaceFileError(path.string() + ": holds face " + std::to_string(header.face) + ", not " + std::to_string(f));
    if (header.radius != first.radius || header.leafLevel != first.leafLevel || header.divisions != first.divisions)
      throw FaceFileError(path.string() +
                          ": is of another build than face-0.bdam (radius, leaf level or divisions "
                          "differ): build the folder again with one `strata build-bdam`");
  }
}

HeightRange BdamData::heights() const {
  HeightRange range{face(0).header().lowest, face(0).header().highest};
  for (const auto& f : faces_)
    range = {std::min(range.lowest, f->header().lowest), std::max(range.highest, f->header().highest)};
  return range;
}

std::uint32_t BdamData::mostVertices() const {
  std::uint32_t most = 0;
  for (const auto& f : faces_) most = std::max(most, f->header().mostVertices);
  return most;
}

std::uint32_t BdamData::mostIndices() const {
  std::uint32_t most = 0;
  for (const auto& f : faces_) most = std::max(most, f->header().mostIndices);
  return most;
}

}  // namespace strata::bdam
