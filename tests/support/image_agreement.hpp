#pragma once
#include "test_rasters.hpp"

namespace strata::test {

// Levels by which a pixel's worst channel differs "largely": far beyond the rounding of 8-bit output (a level
// or two), plainly visible.
constexpr int kLargeDifference = 16;

// How closely two renders of one view agree, over the pixels that both images draw within two pixels of
// (x, y) (a silhouette is left out: two meshes' edges, chords of different spacing, may fall either side of
// a pixel's centre), in 8-bit levels over the three colour channels.
struct ImageAgreement {
  int compared = 0;
  int darkest = 255, brightest = 0;  // of the first image's compared pixels, green: the shading's range
  double meanDifference = 0.0;       // levels
  double largeShare = 0.0;           // of the compared pixels, those whose worst channel differs by more than
                                     // kLargeDifference
};

ImageAgreement agreementAwayFromSilhouettes(const Image& a, const Image& b);

// Whether every pixel within two of (x, y) shows the body (rendering.hpp, covered), clamped at the image's edges.
bool coveredAround(const Image& image, int x, int y);

}  // namespace strata::test
