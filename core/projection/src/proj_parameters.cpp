// Reading a PROJ string's "+key=value" terms, as the projection factories receive them.
#include <charconv>
#include <cmath>
#include <sstream>

#include <strata/error.hpp>
#include <strata/plugin/projection.hpp>

namespace strata {
namespace {

const SourceLocation kProjection{.node = "projection"};

}  // namespace

ProjParameters ProjParameters::parse(const std::string& text) {
  ProjParameters parameters;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    const auto equals = word.find('=');
    const std::string key = word.substr(1, equals == std::string::npos ? std::string::npos : equals - 1);
    if (word.front() != '+' || key.empty())
      throw Error(kProjection, "'" + word + "' in the PROJ string '" + text + "' is not a +key or +key=value term",
                  "write the projection as PROJ terms, e.g. '+proj=stere +lat_0=-90 +lat_ts=-71 +R=3396190'");
    const std::string value = equals == std::string::npos ? std::string() : word.substr(equals + 1);
    parameters.terms_.try_emplace(key, value);  // PROJ reads the first of repeated terms
  }
  return parameters;
}

std::string ProjParameters::name() const {
  const auto found = terms_.find("proj");
  return found == terms_.end() ? std::string() : found->second;
}

double ProjParameters::real(const std::string& key, double fallback) const {
  const auto found = terms_.find(key);
  if (found == terms_.end()) return fallback;
  const std::string& text = found->second;
  // from_chars takes no leading '+', which PROJ strings may carry ("+lat_0=+90").
  const bool plus = text.starts_with('+') && !text.starts_with("+-");
  const char* begin = text.data() + (plus ? 1 : 0);
  const char* end = text.data() + text.size();
  double value = 0.0;
  const auto [stop, status] = std::from_chars(begin, end, value);
  if (begin == end || status != std::errc() || stop != end || !std::isfinite(value))
    throw Error(kProjection, "+" + key + "=" + text + " is not a number",
                "give +" + key + " as a decimal number (degrees for angles), e.g. +" + key + "=-71.5");
  return value;
}

}  // namespace strata
