#pragma once
#include <string>
#include <utility>

#include <cpl_vsi.h>

namespace strata::gdal {

// A file in GDAL's in-memory file system (/vsimem/), removed when this goes. GdalPageSource opens its
// file again by name on every loader thread, so a raster made in memory (a rasterised polygon mask) lives
// in such a file rather than in a MEM dataset, which has no name to open.
class MemoryFile {
 public:
  explicit MemoryFile(std::string path) : path_(std::move(path)) {}
  ~MemoryFile() { VSIUnlink(path_.c_str()); }
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace strata::gdal
