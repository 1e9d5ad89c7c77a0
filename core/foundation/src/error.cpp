#include <strata/error.hpp>

#include <utility>

namespace strata {
namespace {

std::string composeMessage(const SourceLocation& where, const std::string& problem, const std::string& fix) {
  std::string message = where.str() + ": error: " + problem;
  if (!fix.empty()) message += "\n  fix: " + fix;
  return message;
}

}  // namespace

std::string SourceLocation::str() const {
  std::string text = file;
  // A line without a column still helps; a column without a line does not.
  if (line > 0) text += ":" + std::to_string(line) + ":" + std::to_string(column);
  if (!node.empty()) text += " (node '" + node + "')";
  return text;
}

Error::Error(SourceLocation where, std::string problem, std::string fix)
    : std::runtime_error(composeMessage(where, problem, fix)),
      where_(std::move(where)),
      problem_(std::move(problem)),
      fix_(std::move(fix)) {}

}  // namespace strata
