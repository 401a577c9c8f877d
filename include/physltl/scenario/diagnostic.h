#pragma once
// Where a scenario element came from, and what is wrong with it.

#include <stdexcept>
#include <string>
#include <vector>

namespace physltl::scenario {

struct Location {
  std::string file;  // as the user named it, e.g. scenarios/rooms.lua
  int line = 0;

  std::string str() const { return line > 0 ? file + ":" + std::to_string(line) : file; }
};

struct Diagnostic {
  Location where;
  std::string message;

  std::string str() const { return where.str() + ": " + message; }
};

// Every problem found in one scenario, reported together so an author fixes them in one pass.
class ScenarioError : public std::runtime_error {
 public:
  explicit ScenarioError(std::vector<Diagnostic> diagnostics);
  const std::vector<Diagnostic>& diagnostics() const { return diagnostics_; }

 private:
  std::vector<Diagnostic> diagnostics_;
};

}  // namespace physltl::scenario
