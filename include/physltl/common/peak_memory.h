#pragma once
// This program's peak resident memory so far. A process's peak never goes down, so it measures one run
// only in a process of its own (the main job, or a run that bench starts as one).

namespace physltl::common {

double peak_memory_mb();  // MB (10^6 bytes)

}  // namespace physltl::common
