#pragma once
// What `physltl-studio test` checks a scenario against (docs/testing.md): the `expect { ... }` block of
// its top-level file. A scenario without one is expected to solve and validate, with its plan and
// preview matching their goldens.

#include "physltl/scenario/diagnostic.h"

#include <optional>
#include <string>
#include <vector>

namespace physltl::scenario {

// How far a picture may differ from its golden (physltl/render/image_compare.h has the defaults and their why).
struct PictureTolerance {
  std::optional<int> max_channel_difference;    // 0..255
  std::optional<double> max_fraction_beyond;    // share of the pixels, 0..1
};

// A frame of the replayed plan: at `time_s` seconds of motion, or the plan's last state.
struct FrameMoment {
  double time_s = 0.0;
  bool last = false;

  // Its golden's and its JUnit case's name: "frame_12.5s.png" (six significant digits), "frame_last.png".
  // Two moments of one name are refused by the reader.
  std::string file_name() const;
};

struct Expectations {
  // Set: `check` must find the task infeasible with a reason containing this text; nothing is planned.
  std::optional<std::string> infeasible;
  std::vector<std::string> unreachable;  // regions the reasoning must mark unreachable
  // Bounds on the written (improved) plan.
  std::optional<int> max_pushes;
  std::optional<double> max_motion_s;
  std::optional<int> max_bodies_moved;
  // The written plan, replayed in `worlds` perturbed worlds of the scenario's uncertainty (docs/robustness.md,
  // seeded by the scenario's seed), succeeds in at least the share `at_least` of them.
  struct Robustness {
    int worlds = 20;
    double at_least = 0.0;
  };
  std::optional<Robustness> robustness;
  bool tree = false;                 // also compare tree.png
  std::vector<FrameMoment> frames;   // and these frames of the plan
  PictureTolerance tolerance;        // for every picture, unless one of the three below says otherwise
  PictureTolerance preview_tolerance, tree_tolerance, frames_tolerance;
  Location where;
};

}  // namespace physltl::scenario
