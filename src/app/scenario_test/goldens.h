#pragma once
// The goldens of one scenario (`<scenario dir>/goldens/<name>/` or `--goldens DIR/<name>/`) and what a
// mismatch leaves for its author (`<out>/test/<name>/`: <file>.actual.png, <file>.diff.png,
// plan.actual.json).

#include "case_result.h"
#include "physltl/render/image_compare.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace physltl::app::scenario_test {

class Goldens {
 public:
  // `update_line` is the command that writes a missing golden, quoted in the failure.
  Goldens(std::filesystem::path folder, std::filesystem::path actual_folder, bool update, std::string update_line);

  // Exact bytes first, then the tolerance. With update, a picture beyond the tolerance (or a missing one)
  // is written and the case reports it; one within it is left alone, so Mesa's rounding never churns goldens.
  CaseResult picture(const std::string& file_name, const render::Image& actual, const render::Tolerance& tolerance);
  // plan.json as the main job writes it, less where the scenario file lay, its per-step arrays kept at
  // the controls' ends and only for the bodies the plan moves (docs/testing.md).
  CaseResult plan(nlohmann::ordered_json plan);

 private:
  CaseResult missing(const std::string& file_name) const;
  // Why the goldens' folder cannot hold goldens (a file in its place); nothing when it can.
  std::optional<std::string> unusable_folder() const;

  std::filesystem::path folder_;
  std::filesystem::path actual_folder_;
  bool update_;
  std::string update_line_;
};

}  // namespace physltl::app::scenario_test
