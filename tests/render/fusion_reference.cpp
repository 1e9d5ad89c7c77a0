#include "fusion_reference.hpp"

#include <cmath>

namespace strata::test {
namespace {

using Matrix = std::array<LinearColour, 3>;

// IEC 61966-2-1: linear Rec. 709 to CIE XYZ, and its inverse; D65 as the matrix's row sums.
constexpr Matrix kToXyz{
    {{0.4124564, 0.3575761, 0.1804375}, {0.2126729, 0.7151522, 0.0721750}, {0.0193339, 0.1191920, 0.9503041}}};
constexpr Matrix kFromXyz{
    {{3.2404542, -1.5371385, -0.4985314}, {-0.9692660, 1.8760108, 0.0415560}, {0.0556434, -0.2040259, 1.0572252}}};
constexpr LinearColour kWhite{0.9504700, 1.0, 1.0888300};

LinearColour times(const Matrix& m, const LinearColour& v) {
  LinearColour out{};
  for (std::size_t i = 0; i < 3; ++i) out[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
  return out;
}

// CIE 15:2004's f and its inverse.
double labF(double t) { return t > 216.0 / 24389.0 ? std::cbrt(t) : t * 841.0 / 108.0 + 4.0 / 29.0; }
double labFInverse(double f) { return f > 6.0 / 29.0 ? f * f * f : (f - 4.0 / 29.0) * 108.0 / 841.0; }

LinearColour toLab(const LinearColour& colour) {
  const LinearColour xyz = times(kToXyz, colour);
  const double fx = labF(xyz[0] / kWhite[0]), fy = labF(xyz[1]), fz = labF(xyz[2] / kWhite[2]);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

LinearColour fromLab(const LinearColour& lab) {
  const double fy = (lab[0] + 16.0) / 116.0;
  return times(kFromXyz, {labFInverse(fy + lab[1] / 500.0) * kWhite[0], labFInverse(fy),
                          labFInverse(fy - lab[2] / 200.0) * kWhite[2]});
}

// ITU-R BT.709 Y'CbCr (Kr 0.2126, Kb 0.0722) of the sRGB-encoded values, unscaled.
LinearColour toYCbCr(const LinearColour& colour) {
  const double r = srgbEncode(colour[0]), g = srgbEncode(colour[1]), b = srgbEncode(colour[2]);
  const double luma = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  return {luma, (b - luma) / 1.8556, (r - luma) / 1.5748};
}

LinearColour fromYCbCr(const LinearColour& ycc) {
  const double r = ycc[0] + 1.5748 * ycc[2], b = ycc[0] + 1.8556 * ycc[1];
  const double g = (ycc[0] - 0.2126 * r - 0.0722 * b) / 0.7152;
  return {srgbDecode(r), srgbDecode(g), srgbDecode(b)};
}

double greyLightness(double luminance, OpponentSpace space) {
  return space == OpponentSpace::Lab ? 116.0 * labF(luminance) - 16.0 : srgbEncode(luminance);
}

}  // namespace

double relativeLuminance(const LinearColour& c) {
  return kToXyz[1][0] * c[0] + kToXyz[1][1] * c[1] + kToXyz[1][2] * c[2];
}

LinearColour fuse(const LinearColour& colour, double luminance, OpponentSpace space) {
  const bool lab = space == OpponentSpace::Lab;
  LinearColour opponent = lab ? toLab(colour) : toYCbCr(colour);
  opponent[0] += greyLightness(luminance, space) - greyLightness(relativeLuminance(colour), space);
  return lab ? fromLab(opponent) : fromYCbCr(opponent);
}

}  // namespace strata::test
