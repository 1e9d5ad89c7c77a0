// The bodies a pipeline may name, with their radii from the IAU's cartographic report [Archinal 2018].
#include <strata/named_bodies.hpp>

#include <algorithm>
#include <array>
#include <cctype>

namespace strata {
namespace {

constexpr double kKilometre = 1000.0;

// {name, mean, equatorial, polar} in km, as [Archinal 2018] gives them (its tables of the Sun's and the
// planets' sizes and of the satellites'); triaxial bodies by their longest and shortest axes.
constexpr std::array<NamedBody, 26> kBodies{{
    {"Sun", 695700.0, 695700.0, 695700.0},
    {"Mercury", 2440.53, 2440.53, 2438.26},
    {"Venus", 6051.8, 6051.8, 6051.8},
    // The report's mean radius is 6371.0084 km; Strata has drawn the Earth at 6371 km since its first
    // release, and the 8.4 m lie far below what any global raster is registered to.
    {"Earth", 6371.0, 6378.1366, 6356.7519},
    {"Moon", 1737.4, 1737.4, 1737.4},
    {"Mars", 3389.5, 3396.19, 3376.2},
    {"Phobos", 11.08, 13.0, 9.1},
    {"Deimos", 6.2, 7.8, 5.1},
    {"Jupiter", 69911.0, 71492.0, 66854.0},
    {"Io", 1821.49, 1829.4, 1815.7},
    {"Europa", 1560.8, 1562.6, 1559.5},
    {"Ganymede", 2631.2, 2631.2, 2631.2},
    {"Callisto", 2410.3, 2410.3, 2410.3},
    {"Saturn", 58232.0, 60268.0, 54364.0},
    {"Mimas", 198.2, 207.8, 190.6},
    {"Enceladus", 252.1, 256.6, 248.3},
    {"Tethys", 531.0, 538.4, 526.3},
    {"Dione", 561.4, 563.4, 559.6},
    {"Rhea", 763.5, 765.0, 762.4},
    {"Titan", 2575.0, 2575.15, 2574.47},
    {"Iapetus", 734.5, 745.7, 712.1},
    {"Uranus", 25362.0, 25559.0, 24973.0},
    {"Neptune", 24622.0, 24764.0, 24341.0},
    {"Triton", 1352.6, 1352.6, 1352.6},
    {"Pluto", 1188.3, 1188.3, 1188.3},
    {"Charon", 606.0, 606.0, 606.0},
}};

constexpr std::array<NamedBody, kBodies.size()> inMetres() {
  std::array<NamedBody, kBodies.size()> bodies{};
  for (std::size_t i = 0; i < kBodies.size(); ++i) {
    const NamedBody& body = kBodies[i];
    bodies[i] = {body.name, body.meanRadius * kKilometre, body.equatorialRadius * kKilometre,
                 body.polarRadius * kKilometre};
  }
  return bodies;
}

constexpr std::array<NamedBody, kBodies.size()> kBodiesInMetres = inMetres();

bool sameLetters(const std::string& a, const char* b) {
  const std::string_view other(b);
  return std::ranges::equal(a, other, [](char x, char y) {
    return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
  });
}

// How far a radius may lie beyond the ellipsoid's semi-axes and still be the body's.
constexpr double kRadiusSlack = 0.01;

}  // namespace

std::span<const NamedBody> namedBodies() { return kBodiesInMetres; }

const NamedBody* findNamedBody(const std::string& name) {
  for (const NamedBody& body : kBodiesInMetres)
    if (sameLetters(name, body.name)) return &body;
  return nullptr;
}

bool radiusFits(const NamedBody& body, double radius) {
  return radius >= body.polarRadius * (1.0 - kRadiusSlack) && radius <= body.equatorialRadius * (1.0 + kRadiusSlack);
}

}  // namespace strata
