#pragma once
// What holds in a state of the environment, as the task's automaton reads it: the robot's region and, for
// each body or group of bodies the task names (BODY@REGION, ltl/object_atom.h; scenario::Group), which of
// the regions or region groups it is named with holds it. The reasoning (the first letter), the planners,
// replay and the pictures all ask this one piece, so none of them can disagree.
//
// Letters are numbered: letter = facts * (regions + 1) + robot region + 1, where `facts` numbers the
// named parts' places together (mixed radix: each part in none or one of the region sets it is named
// with) and the robot's region is a World region index or -1 (outside every region, the paper's p0). A
// task about the robot alone has one fact set, so its letters are its regions. A group counts as one
// part: "every box on some goal" is one proposition of two places, whatever the number of boxes.

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
  // A body, or a group of bodies, the task names, with the region sets it is named with (a region, or a
  // group of regions) and their propositions. Place k + 1 of the part: every body of it has its centre
  // in some region of region_sets[k]; place 0: otherwise.
  struct NamedPart {
    std::string name;                          // as written: a body's or a group's
    std::vector<int> bodies;                   // World::movable_bodies indices
    std::vector<std::vector<int>> region_sets; // World region indices
    std::vector<std::string> set_names;        // each as written: a region's or a group's
    std::vector<int> propositions;             // dfa proposition of each
    int stride = 1;                            // the part's digit in a fact set
    int places() const { return static_cast<int>(region_sets.size()) + 1; }
    bool has_body(int body) const;
    // The place of one body of it whose centre is in World region `region` (-1: none): k + 1 when region_sets[k] holds it.
    int place_of_region(int region) const;
  };

  // Throws scenario::ScenarioError (at the task's line) when the named parts' places together exceed
  // kMaxFactSets, std::invalid_argument for a proposition naming no body and region of `world`.
  Labelling(const scenario::World& world, const ltl::Dfa& dfa);
  static constexpr int kMaxFactSets = 1 << 16;

  int regions() const { return regions_count_; }
  int fact_sets() const { return fact_sets_; }
  int letters() const { return fact_sets_ * (regions_count_ + 1); }
  const std::vector<NamedPart>& named_parts() const { return named_; }
  // The part naming World body `body`, or -1 when the task leaves it free (validation lets a body be in one).
  int part_of(int body) const;

  int letter(int facts, int robot_region) const { return facts * (regions_count_ + 1) + robot_region + 1; }
  int facts_of(int letter) const { return letter / (regions_count_ + 1); }
  int robot_region_of(int letter) const { return letter % (regions_count_ + 1) - 1; }
  // The place of named part `named` in a fact set: 0 outside its region sets, k + 1 in region_sets[k].
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
  std::vector<NamedPart> named_;
  int fact_sets_ = 1;
  std::vector<std::string> proposition_names_;
};

}  // namespace physltl::knowledge
