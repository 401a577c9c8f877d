#include "physltl/common/output_folder.h"

#include "physltl/common/files.h"
#include "physltl/common/output_paths.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <mutex>
#include <set>
#include <string>
#include <system_error>

namespace physltl::common {
namespace {

namespace fs = std::filesystem;

fs::path sibling(const fs::path& path, const char* tag) {
  return path.parent_path() / (path.filename().string() + tag + std::to_string(::getpid()));
}

// rename(2) replaces a file or an empty folder in one step, but not a folder with contents: move that one
// aside first and delete it once `from` is in place.
void replace(const fs::path& from, const fs::path& to) {
  if (fs::is_directory(to) && !fs::is_empty(to)) {
    const fs::path old = sibling(to, ".old-");
    fs::remove_all(old);
    fs::rename(to, old);
    fs::rename(from, to);
    fs::remove_all(old);
  } else {
    fs::rename(from, to);
  }
}

// "out/rooms/" names the same folder as "out/rooms"; with the slash kept, the temporary folder would land
// inside the final one.
fs::path without_trailing_slash(const fs::path& path) { return path.has_filename() ? path : path.parent_path(); }

// The temporary folders of this process not yet committed or removed, for remove_unfinished_outputs().
// Never destroyed: the stop signal's watchdog may use them while the process exits.
std::mutex& open_folders_mutex() {
  static auto* mutex = new std::mutex;
  return *mutex;
}
std::set<fs::path>& open_folders() {
  static auto* folders = new std::set<fs::path>;
  return *folders;
}

}  // namespace

void remove_unfinished_outputs() {
  remove_unfinished_writes();
  const std::lock_guard lock(open_folders_mutex());
  std::error_code ignored;
  for (const fs::path& folder : open_folders()) fs::remove_all(folder, ignored);
  open_folders().clear();
}

OutputFolder::OutputFolder(const fs::path& final_path, Commit how, const std::vector<fs::path>& inputs)
    : final_(without_trailing_slash(final_path)), temp_(sibling(final_, ".tmp-")), how_(how) {
  if (how_ == Commit::kWhole) check_replaceable(final_, inputs);
  try {
    if (final_.has_parent_path()) fs::create_directories(final_.parent_path());
    remove_leftovers_of_ended_runs(final_);
    fs::remove_all(temp_);
    fs::create_directory(temp_);
  } catch (const fs::filesystem_error& e) {
    // Said of the folder the user knows, not of its temporary sibling.
    if (e.path1() == temp_) throw fs::filesystem_error(e.what(), final_, e.code());
    throw;
  }
  {
    const std::lock_guard lock(open_folders_mutex());
    open_folders().insert(temp_);
  }
  if (how_ == Commit::kWhole) mark_made_here(temp_);
}

OutputFolder::~OutputFolder() {
  {
    const std::lock_guard lock(open_folders_mutex());
    open_folders().erase(temp_);
  }
  if (committed_) return;
  std::error_code ignored;  // nothing useful to do about a failure while unwinding
  fs::remove_all(temp_, ignored);
}

void OutputFolder::commit() {
  if (how_ == Commit::kWhole || !fs::exists(final_)) {
    replace(temp_, final_);
  } else {
    for (const fs::directory_entry& entry : fs::directory_iterator(temp_)) {
      replace(entry.path(), link_target(final_ / entry.path().filename()));
    }
    fs::remove(temp_);
  }
  committed_ = true;
}

}  // namespace physltl::common
