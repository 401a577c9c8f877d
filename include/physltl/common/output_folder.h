#pragma once
// Outputs appear whole or not at all: a command writes into a temporary folder next to the final one and
// commits at the end. A run that fails or is interrupted before commit() leaves the previous outputs as
// they were.

#include <filesystem>
#include <vector>

namespace physltl::common {

// Removes the temporary folders of every OutputFolder of this process not yet committed, and the temporary
// files of writes under way: for a process that must end at once, without unwinding (the physics engine's
// failure, the stop signal's watchdog).
void remove_unfinished_outputs();

class OutputFolder {
 public:
  // How commit() puts the outputs in place.
  enum class Commit {
    // The final folder becomes exactly what was written: a previous one is renamed away, the new one
    // renamed into place, then the old one deleted (only the instant between the two renames has no final
    // folder). The folder must be one the rule lets the command replace (check_replaceable, with the
    // command's `inputs`: checked here, before any work), and the new one holds the marker that says this
    // program made it.
    kWhole,
    // Each entry written replaces its namesake in the final folder by one rename (a symbolic link's target:
    // written through, the link kept), and entries already there that were not written stay (`check`
    // refreshing preview.png beside a plan's outputs, `import` adding levels to a folder). Creates the
    // final folder by renaming the temporary one when there is none yet. The caller checks the folder's
    // name (check_folder_name) where a scenario's name makes it.
    kEntries,
  };

  // Creates the empty folder `<final_path>.tmp-<pid>` (and the parents of `final_path`). Leftovers of runs
  // that were killed (`.tmp-` and `.old-` siblings whose process has ended, or of this pid) are removed
  // first. Throws BadInput when the rule refuses the folder, std::filesystem::filesystem_error when it
  // cannot be made.
  OutputFolder(const std::filesystem::path& final_path, Commit how, const std::vector<std::filesystem::path>& inputs = {});
  // Removes the temporary folder unless committed.
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  // Where to write until commit().
  const std::filesystem::path& path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }

  // Puts the outputs in place as chosen; once.
  void commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path temp_;
  Commit how_;
  bool committed_ = false;
};

}  // namespace physltl::common
