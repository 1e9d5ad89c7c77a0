#pragma once
#include <stdexcept>
#include <strata/export.hpp>
#include <string>

STRATA_EXPORTS_BEGIN
namespace strata {

// Where something a user wrote lives: a file with line and column (1-based), or a pipeline node.
struct SourceLocation {
  std::string file;  // pipeline file, or "--set" for a command-line override
  int line = 0;      // 0 when unknown
  int column = 0;
  std::string node{};  // node id, when the problem belongs to one; {} so SourceLocation{file} warns not

  std::string str() const;  // "file:line:column" or "file (node 'id')"
};

// A problem in the user's input: what is wrong, where, and what would fix it. Every error a user can
// cause reaches them as one of these, never as a crash.
class Error : public std::runtime_error {
 public:
  Error(SourceLocation where, std::string problem, std::string fix = {});

  const SourceLocation& where() const { return where_; }
  const std::string& problem() const { return problem_; }
  const std::string& fix() const { return fix_; }

 private:
  SourceLocation where_;
  std::string problem_;
  std::string fix_;
};

}  // namespace strata
STRATA_EXPORTS_END
