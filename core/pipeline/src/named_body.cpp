#include "named_body.hpp"

#include <strata/host/scene_settings.hpp>
#include <strata/log.hpp>
#include <strata/named_bodies.hpp>

namespace strata::loader {
namespace {

constexpr double kKilometre = 1000.0;

std::string metres(double value) { return formatValue(ParameterValue(value)) + " m"; }

std::string knownNames() {
  std::string names;
  for (const NamedBody& body : namedBodies()) names += (names.empty() ? "" : ", ") + std::string(body.name);
  return names;
}

// The named body whose radii a radius in kilometres would be: `named` where the section names one, else any.
const NamedBody* bodyInKilometres(const NamedBody* named, double radius) {
  if (named) return radiusFits(*named, radius * kKilometre) ? named : nullptr;
  for (const NamedBody& body : namedBodies())
    if (radiusFits(body, radius * kKilometre)) return &body;
  return nullptr;
}

void checkRadius(const ParameterSet& section, const Body& body, const NamedBody* named) {
  const SourceLocation& where = section.where("radius");
  if (named && radiusFits(*named, body.radius)) return;
  if (!named && section.has("name")) return;  // a body Strata does not know may be any size
  if (const NamedBody* meant = bodyInKilometres(named, body.radius))
    throw Error(where,
                "body radius " + formatValue(ParameterValue(body.radius)) + " looks like kilometres: " + meant->name +
                    "'s mean radius is " + metres(meant->meanRadius),
                "give the radius in metres, or name the body and leave the radius out (body: {name: " +
                    std::string(meant->name) + "})");
  if (named)
    logMessage({LogLevel::Warning,
                where.str() + ": body radius " + metres(body.radius) + " is not " + named->name + "'s (mean " +
                    metres(named->meanRadius) + "); the sphere is drawn at the radius given",
                "leave the radius out to take " + std::string(named->name) + "'s, or rename the body"});
}

}  // namespace

Body bodyOf(const ParameterSet& section) {
  Body body = bodyParameters().read(section);
  const NamedBody* named = section.has("name") ? findNamedBody(body.name) : nullptr;
  if (section.has("radius")) {
    checkRadius(section, body, named);
  } else if (named) {
    body.radius = named->meanRadius;
  } else if (section.has("name")) {
    throw Error(section.where("name"), "'" + body.name + "' is not a body Strata knows by name, and no radius is given",
                "give its mean radius in metres (body: {name: " + body.name + ", radius: 1000000}), or name one of " +
                    knownNames());
  }
  return body;
}

}  // namespace strata::loader
