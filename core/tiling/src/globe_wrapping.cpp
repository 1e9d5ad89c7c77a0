#include "globe_wrapping.hpp"

#include <ogr_spatialref.h>
#include <vrtdataset.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace strata::tiling {
namespace {

bool near(double a, double b) { return std::abs(a - b) < 1e-9 * 360.0; }

// Rows [row, row + rows) of `source` at row `vrtRow` of `band`, one more column on each side, turned by
// `shift` columns: VRT column j holds source column (j - 1 + shift) mod the source's width.
void placeWrapped(VRTSourcedRasterBand& band, GDALRasterBand& source, int row, int rows, int vrtRow, int shift) {
  const int width = source.GetXSize();
  for (int column = 0; column < width + 2;) {
    const int from = ((column - 1 + shift) % width + width) % width;
    const int run = std::min(width - from, width + 2 - column);
    band.AddSimpleSource(&source, from, row, run, rows, column, vrtRow, run, rows);
    column += run;
  }
}

}  // namespace

Dataset wrapAroundGlobe(GDALDataset& input) {
  std::array<double, 6> t{};
  const OGRSpatialReference* crs = input.GetSpatialRef();
  const int width = input.GetRasterXSize(), height = input.GetRasterYSize();
  if (!crs || !crs->IsGeographic() || input.GetGeoTransform(t.data()) != CE_None || t[2] != 0.0 || t[4] != 0.0 ||
      t[5] >= 0.0 || !near(crs->GetAngularUnits() * 180.0 / std::numbers::pi, 1.0) || !near(t[1] * width, 360.0))
    return nullptr;
  // The VRT starts at the antimeridian, where PROJ's longitudes do, wherever the input starts (0 degrees is
  // common): its first column is input column `shift`, the one nearest the antimeridian, so that with the
  // columns added on either side it reaches past both -180 and 180 however the texels lie (grids of texel
  // centres, such as EGM96's, start half a texel west of it).
  const int shift = int(std::lround((-180.0 - t[0]) / t[1]));
  // A half turn of longitude must be whole texels for the rows across a pole.
  const bool north = width % 2 == 0 && near(t[3], 90.0), south = width % 2 == 0 && near(t[3] + t[5] * height, -90.0);
  const int top = north ? 1 : 0;
  Dataset wrapped(GetGDALDriverManager()->GetDriverByName("VRT")->Create(
      "", width + 2, height + top + (south ? 1 : 0), 0, input.GetRasterBand(1)->GetRasterDataType(), nullptr));
  wrapped->SetSpatialRef(crs);
  std::array<double, 6> extended{t[0] + (shift - 1) * t[1], t[1], 0.0, t[3] - top * t[5], 0.0, t[5]};
  wrapped->SetGeoTransform(extended.data());
  for (int b = 1; b <= input.GetRasterCount(); ++b) {
    GDALRasterBand& source = *input.GetRasterBand(b);
    wrapped->AddBand(source.GetRasterDataType(), nullptr);
    auto& band = static_cast<VRTSourcedRasterBand&>(*wrapped->GetRasterBand(b));
    int hasNodata = 0;
    const double nodata = source.GetNoDataValue(&hasNodata);
    if (hasNodata) band.SetNoDataValue(nodata);
    band.SetColorInterpretation(source.GetColorInterpretation());
    placeWrapped(band, source, 0, height, top, shift);
    if (north) placeWrapped(band, source, 0, 1, 0, shift + width / 2);
    if (south) placeWrapped(band, source, height - 1, 1, top + height, shift + width / 2);
  }
  return wrapped;
}

}  // namespace strata::tiling
