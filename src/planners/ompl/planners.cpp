#include "planners.h"

#include "ompl_planner.h"

#include <ompl/control/planners/kpiece/KPIECE1.h>
#include <ompl/control/planners/ltl/LTLPlanner.h>
#include <ompl/control/planners/ltl/LTLSpaceInformation.h>
#include <ompl/control/planners/pdst/PDST.h>
#include <ompl/control/planners/rrt/RRT.h>
#include <ompl/control/planners/sst/SST.h>

#include <stdexcept>

namespace physltl::planners::ompl {
namespace {

// RNG::setLocalSeed: OMPL's process-wide RNG::setSeed takes effect only before the first generator exists.
template <class Planner>
class Seeded : public Planner {
 public:
  template <class... Args>
  explicit Seeded(std::uint_fast32_t seed, Args&&... args) : Planner(std::forward<Args>(args)...) {
    this->rng_.setLocalSeed(seed);
  }
};

// OMPL 1.5's SST deletes its witnesses without freeing their states and controls (SST::freeMemory; still
// so in OMPL's master), which leaks a state and a control per witness every run: free them first.
class SeededSst : public Seeded<oc::SST> {
 public:
  using Seeded<oc::SST>::Seeded;
  ~SeededSst() override {
    if (!witnesses_) return;
    std::vector<Motion*> witnesses;
    witnesses_->list(witnesses);
    for (Motion* w : witnesses) {
      if (w->state_ != nullptr) si_->freeState(w->state_);
      if (w->control_ != nullptr) siC_->freeControl(w->control_);
      w->state_ = nullptr;
      w->control_ = nullptr;
    }
  }
};

}  // namespace

ob::PlannerPtr make_planner(OmplAlgorithm algorithm, const oc::SpaceInformationPtr& si, const oc::ProductGraphPtr& product,
                            const ob::ProjectionEvaluatorPtr& projection, std::uint_fast32_t seed) {
  switch (algorithm) {
    case OmplAlgorithm::kLtl:
      return std::make_shared<Seeded<oc::LTLPlanner>>(seed, std::static_pointer_cast<oc::LTLSpaceInformation>(si), product,
                                                      kLtlExploreTime);
    case OmplAlgorithm::kRrt:
      return std::make_shared<Seeded<oc::RRT>>(seed, si);
    case OmplAlgorithm::kKpiece: {
      auto planner = std::make_shared<Seeded<oc::KPIECE1>>(seed, si);
      planner->setProjectionEvaluator(projection);
      return planner;
    }
    case OmplAlgorithm::kSst:
      return std::make_shared<SeededSst>(seed, si);
    case OmplAlgorithm::kPdst: {
      auto planner = std::make_shared<Seeded<oc::PDST>>(seed, si);
      planner->setProjectionEvaluator(projection);
      return planner;
    }
  }
  throw std::invalid_argument("not an OMPL planner");
}

}  // namespace physltl::planners::ompl
