#include "goldens.h"

#include "physltl/common/files.h"
#include "views/report_files.h"

#include "physltl/render/png.h"

#include <fmt/format.h>

#include <cstdint>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

namespace physltl::app::scenario_test {
namespace {

// Whole or not at all: a golden interrupted half-way would fail every later run.
void write_text(const std::filesystem::path& file, std::string_view text) {
  std::filesystem::create_directories(file.parent_path());
  common::write_text_file(file, text);
}

void write_picture(const render::Image& image, const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = render::encode_png(image);
  write_text(file, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

// A golden plan holds the plan's states at each control's end: far below this.
constexpr std::size_t kMaxGoldenBytes = std::size_t{64} << 20;

// plan.json's per-step arrays (states, traces) at the start and at each control's end, and of the bodies
// only those the plan moves: for the same controls the replay between is the same physics, and a golden of
// every step of 200 bodies would weigh megabytes. One state per line, so a diff names the control.
std::string golden_plan_text(nlohmann::ordered_json plan) {
  plan = plan_with_every_pose(std::move(plan));
  plan["scenario"] = std::filesystem::path(plan["scenario"].get<std::string>()).filename().string();
  std::vector<std::size_t> steps{0};
  for (const auto& control : plan["controls"]) steps.push_back(steps.back() + control["steps"].get<std::size_t>());
  std::vector<std::size_t> moved;
  for (const auto& name : plan["moved_bodies"]) {
    for (std::size_t b = 0; b < plan["body_names"].size(); ++b) {
      if (plan["body_names"][b] == name) moved.push_back(b);
    }
  }
  nlohmann::ordered_json golden;
  for (auto& [key, value] : plan.items()) {
    if (!value.is_array() || value.size() != steps.back() + 1 || key == "controls") {
      golden[key] = value;
      continue;
    }
    nlohmann::ordered_json sampled = nlohmann::ordered_json::array();
    for (std::size_t step : steps) {
      nlohmann::ordered_json item = value[step];
      if (key == "states") {
        nlohmann::ordered_json bodies = nlohmann::ordered_json::array();
        for (std::size_t b : moved) bodies.push_back(item["bodies"][b]);
        item["bodies"] = bodies;
      }
      sampled.push_back(item);
    }
    golden[key] = sampled;
  }
  golden["golden_steps"] = steps;
  std::string text = "{\n";
  bool first = true;
  for (const auto& [key, value] : golden.items()) {
    text += (first ? "" : ",\n") + common::json_text(nlohmann::ordered_json(key)) + ": ";
    first = false;
    if (!value.is_array() || value.empty()) {
      text += common::json_text(value);
      continue;
    }
    text += "[\n";
    for (std::size_t i = 0; i < value.size(); ++i) text += "  " + common::json_text(value[i]) + (i + 1 < value.size() ? ",\n" : "\n");
    text += "]";
  }
  return text + "\n}\n";
}

std::string percent(double fraction) { return fmt::format("{:.3f}%", 100.0 * fraction); }

}  // namespace

Goldens::Goldens(std::filesystem::path folder, std::filesystem::path actual_folder, bool update, std::string update_line)
    : folder_(std::move(folder)), actual_folder_(std::move(actual_folder)), update_(update), update_line_(std::move(update_line)) {}

CaseResult Goldens::missing(const std::string& file_name) const {
  return {file_name, Outcome::kFailed,
          fmt::format("no golden {}; write it with: {}", (folder_ / file_name).string(), update_line_)};
}

CaseResult Goldens::picture(const std::string& file_name, const render::Image& actual, const render::Tolerance& tolerance) {
  const std::filesystem::path golden = folder_ / file_name;
  if (const auto why = unusable_folder()) return {file_name, Outcome::kFailed, *why};
  const bool exists = std::filesystem::exists(golden);
  if (!exists && !update_) return missing(file_name);
  std::optional<render::Image> readable;
  if (exists) {
    try {
      readable = render::read_png(golden);
    } catch (const std::runtime_error& e) {
      // A golden that cannot be read is one --update rewrites.
      if (!update_) return {file_name, Outcome::kFailed, std::string(e.what()) + "; rewrite it with: " + update_line_};
    }
  }
  if (readable) {
    const render::Image& expected = *readable;
    const render::Comparison result = render::compare_images(expected, actual, tolerance);
    if (result.within(tolerance)) return {file_name, Outcome::kPassed, ""};
    if (!update_) {
      const std::filesystem::path stem = actual_folder_ / std::filesystem::path(file_name).stem();
      const std::filesystem::path actual_path = stem.string() + ".actual.png";
      write_picture(actual, actual_path);
      if (!result.same_size) {
        return {file_name, Outcome::kFailed,
                fmt::format("{} is {}x{}, its golden {} is {}x{}; actual picture: {}", file_name, actual.width,
                            actual.height, golden.string(), expected.width, expected.height, actual_path.string())};
      }
      const std::filesystem::path diff_path = stem.string() + ".diff.png";
      write_picture(render::amplified_difference(expected, actual, tolerance), diff_path);
      return {file_name, Outcome::kFailed,
              fmt::format("{} differs from {}: {} of the pixels by more than {} (allowed {}), largest difference {}; "
                          "diff (x16, magenta beyond the tolerance): {}; actual: {}",
                          file_name, golden.string(), percent(result.fraction_beyond), tolerance.max_channel_difference,
                          percent(tolerance.max_fraction_beyond), result.largest_difference, diff_path.string(),
                          actual_path.string())};
    }
  }
  write_picture(actual, golden);
  return {file_name, Outcome::kUpdated, (exists ? "updated " : "wrote ") + golden.string()};
}

std::optional<std::string> Goldens::unusable_folder() const {
  if (std::filesystem::exists(folder_) && !std::filesystem::is_directory(folder_)) {
    return folder_.string() + " is a file, not a folder of goldens";
  }
  return std::nullopt;
}

CaseResult Goldens::plan(nlohmann::ordered_json plan) {
  const std::string file_name = "plan.json";
  // The same scenario tested from another folder plans the same: where its file lay is no part of the plan.
  const std::string text = golden_plan_text(std::move(plan));
  const std::filesystem::path golden = folder_ / file_name;
  if (const auto why = unusable_folder()) return {file_name, Outcome::kFailed, *why};
  const bool exists = std::filesystem::exists(golden);
  if (!exists && !update_) return missing(file_name);
  if (exists) {
    const std::string expected_text = common::read_input_file(golden, kMaxGoldenBytes);
    if (expected_text == text) return {file_name, Outcome::kPassed, ""};
    if (!update_) {
      const std::filesystem::path actual_path = actual_folder_ / "plan.actual.json";
      write_text(actual_path, text);
      nlohmann::json expected;
      try {
        expected = common::parse_json(expected_text);
      } catch (const nlohmann::json::exception& e) {
        return {file_name, Outcome::kFailed, fmt::format("{} is not JSON ({}); actual: {}", golden.string(), e.what(), actual_path.string())};
      }
      const nlohmann::json patch = nlohmann::json::diff(expected, nlohmann::json::parse(text));
      const std::string where = patch.empty() ? "in layout only" : "first at " + patch[0]["path"].get<std::string>();
      return {file_name, Outcome::kFailed,
              fmt::format("the plan changed: plan.json differs from {} ({} difference{}, {}); actual: {}", golden.string(),
                          patch.size(), patch.size() == 1 ? "" : "s", where, actual_path.string())};
    }
  }
  write_text(golden, text);
  return {file_name, Outcome::kUpdated, (exists ? "updated " : "wrote ") + golden.string()};
}

}  // namespace physltl::app::scenario_test
