#pragma once
#include <span>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// A body of the solar system a pipeline may name (`body: {name: Mars}`): its mean radius, which Strata's
// sphere takes, and the semi-axes of its reference ellipsoid, which rasters of it are often given on. Values
// of the IAU Working Group on Cartographic Coordinates and Rotational Elements [Archinal 2018, Tables 1,
// 4, 5]; a body the report takes as a sphere has its mean radius for both semi-axes.
struct NamedBody {
  const char* name;
  double meanRadius;        // m
  double equatorialRadius;  // m, the ellipsoid's semi-major axis
  double polarRadius;       // m, its semi-minor axis
};

// Every body known by name: the Sun, its planets, the Moon, Pluto and the large moons.
std::span<const NamedBody> namedBodies();

// The body called `name`, whatever its letters' case; nullptr for a name not in namedBodies().
const NamedBody* findNamedBody(const std::string& name);

// Whether a sphere of `radius` (m) is a fair stand-in for `body`: within 1% of its ellipsoid's semi-axes,
// which holds the mean radius and every radius rasters of it are given on (an Earth raster on WGS 84's
// 6378137 m is the Earth; one on 3396190 m is of Mars).
bool radiusFits(const NamedBody& body, double radius);

}  // namespace strata
STRATA_EXPORTS_END
