#pragma once
// The folder tests/bad_scenarios/: each file makes one mistake and names, on its first line, the
// diagnostic it must produce:  -- expect: LINE: text the message contains
// Read by the loader's table test and by the command-line one (tests/app).

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <vector>

namespace physltl::testing_support {

inline std::vector<std::string> bad_scenario_files() {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(std::string(PHYSLTL_SOURCE_DIR) + "/tests/bad_scenarios")) {
    if (e.path().extension() == ".lua") files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

struct ExpectedDiagnostic {
  int line = 0;
  std::string text;  // a part of the message
};

// nullopt when the first line is not a well-formed `-- expect:` header.
inline std::optional<ExpectedDiagnostic> expected_diagnostic(const std::string& path) {
  std::ifstream in(path);
  std::string header;
  std::getline(in, header);
  std::smatch m;
  if (!std::regex_match(header, m, std::regex("-- expect: (\\d+): (.*)"))) return std::nullopt;
  return ExpectedDiagnostic{std::stoi(m[1]), m[2]};
}

// The test name for a file: its stem.
inline std::string bad_scenario_name(const std::string& path) { return std::filesystem::path(path).stem().string(); }

}  // namespace physltl::testing_support
