#pragma once
// Outputs appear whole or not at all: a command writes into a temporary folder next to the final one and
// commits at the end. A run that fails or is interrupted before commit() leaves the previous outputs as
// they were.

#include <filesystem>

namespace physltl::common {

// Removes the temporary folders of every OutputFolder of this process not yet committed, and the temporary
// files of writes under way: for a process that must end at once, without unwinding (the physics engine's
// failure, the stop signal's watchdog).
void remove_unfinished_outputs();

class OutputFolder {
 public:
  // Creates the empty folder `<final_path>.tmp-<pid>` (and the parents of `final_path`). Leftovers of runs
  // that were killed (`.tmp-` and `.old-` siblings whose process has ended, or of this pid) are removed
  // first. Throws std::filesystem::filesystem_error.
  explicit OutputFolder(const std::filesystem::path& final_path);
  // Removes the temporary folder unless committed.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // Where to write until commit().
  const std::filesystem::path& path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }

  // Call one of the two commits, once.
  // The final folder becomes exactly what was written: a previous one is renamed away, the new one renamed
  // into place, then the old one deleted. Only the instant between the two renames has no final folder.
  void commit();
  // Each entry written replaces its namesake in the final folder by one rename (a symbolic link's target:
  // written through, the link kept), and entries already there that were not written stay (e.g. `check`
  // refreshing preview.png beside a plan's outputs). Creates the final folder by renaming the temporary one
  // when there is none yet.
  void commit_entries();

 private:
  std::filesystem::path final_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

}  // namespace physltl::common
