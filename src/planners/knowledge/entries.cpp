// The knowledge planner and the baseline as registry entries (planning/planner_entry.h): one tree search,
// with and without the knowledge framework.

#include "physltl/planners/knowledge/entries.h"

#include "planner_data.h"
#include "tree_search.h"

namespace physltl::planners::knowledge {
namespace {

using planning::PlannerData;
using planning::Problem;

std::shared_ptr<const PlannerData> prepare_knowledge(const Problem& problem, const planning::PreparationOptions& options) {
  auto prepared = std::make_shared<KnowledgePreparation>();
  // One stage graph for the route choice, the look-ahead and the search: with 16 named bodies it takes
  // half a second to build.
  prepared->stages = std::make_shared<const planning::StageGraph>(problem.task);
  prepared->routes = choose_routes(problem.world, problem.task, *prepared->stages, problem.decomposition, options.deadline);
  const long long arrangements = options.preview ? lookahead::kPreviewArrangements
                                                 : lookahead::run_arrangements(problem.time_limit_s);
  prepared->lookahead = lookahead::look_ahead(problem.world, problem.knowledge, problem.task, *prepared->stages, options.deadline, arrangements);
  prepared->task_names_bodies = problem.task.names_bodies();
  return prepared;
}

planning::PlannerEntry tree_search_entry(std::string name, std::string summary, TreeSearchMode mode) {
  planning::PlannerEntry entry;
  entry.name = std::move(name);
  entry.summary = std::move(summary);
  entry.can = {{}, {}, {}, true};
  entry.uses_knowledge = mode == TreeSearchMode::kKnowledge;
  entry.own_refusals = kOwnRefusalNames;
  entry.report_keys = {"lookahead"};
  entry.diagnosis_keys = {"search_end"};
  if (entry.uses_knowledge) {
    entry.prepare = prepare_knowledge;
    entry.parameters = {push_primitives_parameter()};
  }
  entry.plan = [mode](const Problem& problem, const PlannerData* prepared, const planning::PlannerOptions& options) {
    return plan_with_tree_search(problem, dynamic_cast<const KnowledgePreparation*>(prepared), options, mode);
  };
  entry.account = knowledge_account;
  return entry;
}

}  // namespace

void add_knowledge_planners(planning::PlannerRegistry& registry) {
  registry.add(tree_search_entry("knowledge", "ours with the knowledge framework (the paper's planner)",
                                 TreeSearchMode::kKnowledge));
  registry.add(tree_search_entry("baseline",
                                 "ours without knowledge: fixed-body contacts only, uniform controls (the paper's simple planner)",
                                 TreeSearchMode::kBaseline));
}

}  // namespace physltl::planners::knowledge
