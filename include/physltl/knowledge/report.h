#pragma once
// JSON views of the knowledge layer, for `physltl-studio check --json` and report.json.
// Keys are documented in docs/knowledge.md.

#include "physltl/knowledge/abstract_knowledge.h"
#include "physltl/knowledge/feasibility.h"
#include "physltl/knowledge/kappa.h"
#include "physltl/scenario/state.h"

#include <nlohmann/json.hpp>

#include <string>

namespace physltl::knowledge {

// "+x", "-y"... for a direction within half a degree of a world axis, else its components: "[0.71, 0.71]".
std::string direction_name(const geometry::Vec2& direction);

// K itself: workspace, robot capabilities, body classes with their properties and mRegion templates,
// proposition names.
nlohmann::ordered_json to_json(const AbstractKnowledge& knowledge);

// What `check` reports: "bodies" (class, type in `state`, active/inactive mRegions, allowed push
// directions in the world frame), "regions" (reachable, reason) and "invalid_propositions" (names).
nlohmann::ordered_json knowledge_report(const AbstractKnowledge& knowledge, const scenario::EnvironmentState& state,
                                        const Kappa& kappa, const Feasibility& feasibility);

}  // namespace physltl::knowledge
