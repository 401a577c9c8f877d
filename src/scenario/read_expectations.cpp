#include "read_expectations.h"

#include "physltl/scenario/world.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>

namespace physltl::scenario {
namespace {

PictureTolerance read_tolerance(TableReader& r) {
  PictureTolerance t;
  if (auto channel = r.optional_number("max_channel_difference")) {
    if (!(*channel >= 0 && *channel <= 255 && *channel == std::floor(*channel))) {  // NaN fails too
      r.error("'max_channel_difference' must be a whole number from 0 to 255");
    } else {
      t.max_channel_difference = static_cast<int>(*channel);
    }
  }
  if (auto share = r.optional_number("max_share_beyond")) {
    if (*share < 0 || *share > 1) {
      r.error("'max_share_beyond' must be a share of the pixels, from 0 to 1");
    } else {
      t.max_fraction_beyond = *share;
    }
  }
  return t;
}

// All the digits that tell `value` apart: 12.5000000001, where messages otherwise round to six.
std::string shortest_text(double value) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  return std::string(buffer, end);
}

std::vector<FrameMoment> read_frames(TableReader& r) {
  std::vector<FrameMoment> frames;
  const LuaValue* list = r.list("frames");
  if (list == nullptr) return frames;
  std::map<std::string, const LuaValue*> named;
  for (const LuaValue& item : list->array) {
    if (item.kind == LuaValue::Kind::kNumber && item.number >= 0 && item.number <= 1e6) {
      frames.push_back({item.number, false});
    } else if (item.kind == LuaValue::Kind::kString && item.string == "last") {
      frames.push_back({0.0, true});
    } else {
      r.error("'frames' lists seconds of motion (0 to 1e6) or \"last\", e.g. frames = { 0, 12.5, \"last\" }");
      return {};
    }
    // Two moments of one golden name would be one golden compared twice, and two JUnit cases of one name.
    const auto [at, fresh] = named.emplace(frames.back().file_name(), &item);
    if (!fresh) {
      r.error("'frames' lists " + frames.back().file_name() + " twice" +
              (item.kind == LuaValue::Kind::kNumber && at->second->number != item.number
                   ? " (" + shortest_text(at->second->number) + " s and " + shortest_text(item.number) +
                         " s name one golden: times must differ in their first six digits)"
                   : ""));
      return {};
    }
  }
  return frames;
}

std::optional<int> read_bound(TableReader& r, const std::string& key) {
  const std::optional<double> v = r.optional_number(key);
  if (!v) return std::nullopt;
  if (!(*v >= 0 && *v <= 1e9 && *v == std::floor(*v))) {  // checked before the cast: 1e308 is no int
    r.error("'" + key + "' must be a whole number from 0 to 1e9, got " + number_text(*v));
    return std::nullopt;
  }
  return static_cast<int>(*v);
}

Expectations::Robustness read_robustness(TableReader& r) {
  Expectations::Robustness robustness;
  const double worlds = r.number("worlds", robustness.worlds);
  if (!(worlds >= 1 && worlds <= 10000 && worlds == std::floor(worlds))) {
    r.error("'worlds' must be a whole number from 1 to 10000, got " + number_text(worlds));
  } else {
    robustness.worlds = static_cast<int>(worlds);
  }
  robustness.at_least = r.number("at_least");
  // 0 passes any plan: the expectation would compare nothing.
  if (!(robustness.at_least > 0 && robustness.at_least <= 1)) {
    r.error("'at_least' is the share of worlds the plan must succeed in, more than 0 and at most 1, got " +
            number_text(robustness.at_least));
  }
  return robustness;
}

}  // namespace

std::string FrameMoment::file_name() const {
  return last ? "frame_last.png" : "frame_" + number_text(time_s) + "s.png";
}

Expectations read_expectations(TableReader& r) {
  Expectations e;
  const std::optional<bool> solved = r.has("solved") ? std::optional<bool>(r.boolean("solved", true)) : std::nullopt;
  if (r.has("infeasible")) {
    e.infeasible = r.string("infeasible");
    // Every reason contains the empty text: the expectation would pass any infeasible task.
    if (e.infeasible->empty()) r.error("'infeasible' is the text the reason must contain, and may not be empty");
  }
  if (solved && *solved == bool(e.infeasible)) {
    r.error(e.infeasible ? "'solved = true' and 'infeasible' contradict each other"
                         : "'solved = false' needs 'infeasible = \"...\"', the text the reason must contain");
  }
  e.unreachable = r.strings("unreachable");
  e.max_pushes = read_bound(r, "max_pushes");
  e.max_bodies_moved = read_bound(r, "max_bodies_moved");
  if (auto motion = r.optional_number("max_motion_s")) {
    if (*motion < 0) r.error("'max_motion_s' must be 0 or more");
    e.max_motion_s = *motion;
  }
  if (auto robust = r.nested("robustness")) {
    e.robustness = read_robustness(*robust);
    robust->finish();
  }
  e.tree = r.boolean("tree", false);
  e.frames = read_frames(r);
  if (auto t = r.nested("tolerance")) {
    e.tolerance = read_tolerance(*t);
    for (auto [key, slot] : {std::pair{"preview", &e.preview_tolerance}, std::pair{"tree", &e.tree_tolerance},
                             std::pair{"frames", &e.frames_tolerance}}) {
      if (auto picture = t->nested(key)) {
        *slot = read_tolerance(*picture);
        picture->finish();
        const bool compared = key == std::string("preview") || (key == std::string("tree") ? e.tree : !e.frames.empty());
        if (!compared) {
          t->error(std::string("a tolerance for ") + key + " is given, but " +
                   (key == std::string("tree") ? "tree.png is not compared ('tree = true')" : "no frame is compared ('frames')"));
        }
      }
    }
    t->finish();
  }
  if (e.infeasible && (e.max_pushes || e.max_bodies_moved || e.max_motion_s || e.robustness || e.tree || !e.frames.empty())) {
    r.error("an infeasible scenario plans nothing: bounds, 'robustness', 'tree' and 'frames' need a plan");
  }
  return e;
}

void check_expectations(const World& world, std::vector<Diagnostic>& diagnostics) {
  if (!world.expect) return;
  const Expectations& e = *world.expect;
  for (const std::string& name : e.unreachable) {
    bool known = false;
    for (const Region& region : world.regions) known = known || region.name == name;
    if (!known) diagnostics.push_back({e.where, "expect: 'unreachable' names '" + name + "', which is no region"});
  }
  const bool uncertain = !world.uncertainty.none() || std::ranges::any_of(world.movable_bodies, [](const MovableBody& b) {
    const BodyUncertainty& u = b.uncertainty;
    return u.mass.value_or(0) > 0 || u.friction.value_or(0) > 0 || u.pose.value_or(0) > 0 || u.yaw_deg.value_or(0) > 0;
  });
  if (e.robustness && !uncertain) {
    diagnostics.push_back({e.where, "expect: 'robustness' needs an uncertainty { ... } block (or a body's own): in the model "
                                    "itself every world is the same and the plan succeeds in all"});
  }
}

}  // namespace physltl::scenario
