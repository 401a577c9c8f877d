#pragma once
// What each part of one run took: report.json's times_s, which a campaign reads back from a run it made in
// a process of its own.

namespace physltl::common {

struct PartTimes {
  double prepare_s = 0.0, search_s = 0.0, replay_s = 0.0, improve_s = 0.0, write_plan_s = 0.0;
};

}  // namespace physltl::common
