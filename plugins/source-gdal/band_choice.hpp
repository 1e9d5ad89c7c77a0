#pragma once
#include <gdal_priv.h>

#include <memory>

#include <strata/error.hpp>
#include <strata/plugin/port.hpp>

#include "memory_file.hpp"

namespace strata::gdal {

// The raster a layer of `kind` reads: the file's one band, or the band `band` (1 the first; 0 where the
// pipeline gives none) of a multi-band file as a one-band VRT in memory, which every reader takes as band 1;
// for a normal map whose green points south, the file with its green band inverted, as a VRT likewise.
struct ChosenBand {
  std::unique_ptr<GDALDataset> dataset;
  std::shared_ptr<const MemoryFile> file;  // the VRT's, where one was made
};

struct BandOptions {
  LayerKind kind;
  int band = 0;
  SourceLocation kindWhere;  // the source's `kind`
  SourceLocation bandWhere;  // its `band`
  bool greenSouth = false;   // a normal map's green points south: inverted, so that it points north
};

// Throws strata::Error, with a fix, where a one-channel kind is given a multi-band file without a `band`
// (an alpha band aside: it is the layer's coverage), where `band` lies beyond the file's bands, and where a
// colour or normal layer, which reads three bands, is given one.
ChosenBand chooseBand(std::unique_ptr<GDALDataset> dataset, const BandOptions& options);

}  // namespace strata::gdal
