#pragma once
// JUnit XML as CI servers read it (Jenkins, GitLab, GitHub's test reporters): one <testsuite> per
// scenario, one <testcase> per expectation, <failure> with the message (and so the diff's path), times.

#include "case_result.h"

#include <filesystem>
#include <vector>

namespace physltl::app::scenario_test {

// Written whole or not at all. Throws std::runtime_error when the file cannot be written.
void write_junit(const std::vector<ScenarioResult>& results, const std::filesystem::path& file);

}  // namespace physltl::app::scenario_test
