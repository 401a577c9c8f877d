#include "robustness_report.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace physltl::app {

nlohmann::ordered_json uncertainty_json(const scenario::Uncertainty& u) {
  return {{"mass", u.mass}, {"friction", u.friction}, {"start", u.start}, {"body_pose", u.body_pose},
          {"body_yaw_deg", u.body_yaw_deg}};
}

nlohmann::ordered_json robustness_json(const execution::Robustness& robustness, const scenario::Uncertainty& uncertainty) {
  nlohmann::ordered_json failures = nlohmann::ordered_json::object();
  for (const char* kind : execution::kFailureKinds) {
    const auto it = robustness.failures.find(kind);
    failures[kind] = it == robustness.failures.end() ? 0 : it->second;
  }
  return {{"worlds", robustness.worlds},
          {"asked", robustness.asked},
          {"stopped_by", robustness.stopped.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(robustness.stopped)},
          {"succeeded", robustness.succeeded},
          {"share", robustness.worlds > 0 ? nlohmann::ordered_json(robustness.share()) : nlohmann::ordered_json(nullptr)},
          {"uncertainty", uncertainty_json(uncertainty)},
          {"failures", std::move(failures)}};
}

std::string robustness_line(const execution::Robustness& robustness, const scenario::Uncertainty& u) {
  std::vector<std::string> declared;
  if (u.mass > 0) declared.push_back(fmt::format("mass {:g}", u.mass));
  if (u.friction > 0) declared.push_back(fmt::format("friction {:g}", u.friction));
  if (u.start > 0) declared.push_back(fmt::format("start {:g} m", u.start));
  if (u.body_pose > 0) declared.push_back(fmt::format("body pose {:g} m", u.body_pose));
  if (u.body_yaw_deg > 0) declared.push_back(fmt::format("body yaw {:g} deg", u.body_yaw_deg));
  std::vector<std::string> failures;
  for (const char* kind : execution::kFailureKinds) {
    const auto it = robustness.failures.find(kind);
    if (it != robustness.failures.end()) failures.push_back(fmt::format("{} {}", kind, it->second));
  }
  const std::string cut = robustness.stopped.empty()
                              ? ""
                              : fmt::format(" (cut short by the {} after {} of {} worlds)", robustness.stopped, robustness.worlds,
                                            robustness.asked);
  return fmt::format("{}/{} perturbed worlds succeed open loop ({}){}{}", robustness.succeeded, robustness.worlds,
                     declared.empty() ? "no uncertainty declared" : fmt::format("{}", fmt::join(declared, ", ")), cut,
                     failures.empty() ? "" : fmt::format("; failures: {}", fmt::join(failures, ", ")));
}

}  // namespace physltl::app
