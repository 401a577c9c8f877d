#pragma once
// The look-ahead (planning/lookahead/push_plan.h) as check, the main job and report.json show it
// (docs/report.md).

#include "physltl/planners/knowledge/push_plan.h"
#include "physltl/render/scene.h"
#include "physltl/scenario/world.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace physltl::app {

// "7 pushes: M1 +x 0.6 m, ...", or why there are none: "off: <the rule's reason>".
std::string lookahead_line(const planning::PushPlan& plan, const scenario::World& world);

// {"applies", "reason", "step", "outcome", "arrangements", "pushes": [{"body", "direction", "distance",
// "from", "to"}]}
nlohmann::ordered_json lookahead_json(const planning::PushPlan& plan, const scenario::World& world);

// The pushes as arrows on the floor, from where each body's centre starts to where the push leaves it,
// the first lightest and the last darkest (tree.png and the frames).
std::vector<render::SegmentOverlay> push_arrows(const planning::PushPlan& plan);
// The legend's line for them.
std::string push_arrows_legend(const planning::PushPlan& plan);

}  // namespace physltl::app
