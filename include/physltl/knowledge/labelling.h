#pragma once
// What holds in a state of the environment, as the task's automaton reads it: the robot's region and, for
// each body the task names (BODY@REGION, ltl/object_atom.h), which region its centre is in. The reasoning
// (the first letter), the planners, replay and the pictures all ask this one piece, so none of them can
// disagree.
//
// Letters are numbered: letter = facts * (regions + 1) + robot region + 1, where `facts` numbers the
// named bodies' places together (mixed radix: each body in none or one of the regions it is named with)
// and the robot's region is a World region index or -1 (outside every region, the paper's p0). A task
// about the robot alone has one fact set, so its letters are its regions.

#include "physltl/ltl/dfa.h"
#include "physltl/scenario/state.h"
#include "physltl/scenario/world.h"

#include <string>
#include <vector>

namespace physltl::knowledge {

// Which region contains a point. Asked after every physics step, so each region's bounding box is tried
// before its polygon.
class RegionMap {
 public:
  explicit RegionMap(const scenario::World& world);
  // The region containing `p`, or -1 outside every region. Regions are disjoint.
  int at(const scenario::Vec2& p) const;

 private:
  const scenario::World* world_;
  std::vector<geometry::Rect> bounds_;  // World::regions order
};

class Labelling {
 public:
  // A body the task names, with the regions it is named with and their propositions.
  struct NamedBody {
    int body;                   // World::movable_bodies index
    std::vector<int> regions;   // World region indices; place k + 1 of the body means regions[k]
    std::vector<int> propositions;  // dfa proposition of each
    int stride;                 // the body's digit in a fact set
  };

  // Throws scenario::ScenarioError (at the task's line) when the named bodies' places together exceed
  // kMaxFactSets, std::invalid_argument for a proposition naming no body and region of `world`.
  Labelling(const scenario::World& world, const ltl::Dfa& dfa);
  static constexpr int kMaxFactSets = 1 << 16;

  int regions() const { return regions_count_; }
  int fact_sets() const { return fact_sets_; }
  int letters() const { return fact_sets_ * (regions_count_ + 1); }
  const std::vector<NamedBody>& named_bodies() const { return named_; }

  int letter(int facts, int robot_region) const { return facts * (regions_count_ + 1) + robot_region + 1; }
  int facts_of(int letter) const { return letter / (regions_count_ + 1); }
  int robot_region_of(int letter) const { return letter % (regions_count_ + 1) - 1; }
  // The place of named body `named` in a fact set: 0 outside its regions, k + 1 in regions[k].
  int place(int facts, int named) const;
  int with_place(int facts, int named, int place) const;

  int letter(const scenario::EnvironmentState& state) const;
  // The fact set of the bodies' centres: `centres[b]` of World body b.
  int facts(const scenario::EnvironmentState& state) const;

  // The automaton's propositions true in a letter, ascending.
  std::vector<int> true_propositions(int letter) const;
  // The object atoms true in a fact set, as written: "crate@dock".
  std::vector<std::string> object_facts(int facts) const;

 private:
  RegionMap map_;
  int regions_count_;
  std::vector<int> robot_proposition_;  // per region, its proposition or -1 when the task does not name it
  std::vector<NamedBody> named_;
  int fact_sets_ = 1;
  std::vector<std::string> proposition_names_;
};

}  // namespace physltl::knowledge
