#include "physltl/common/output_paths.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"

#include <algorithm>
#include <array>
#include <string_view>

namespace physltl::common {
namespace {

namespace fs = std::filesystem;

fs::path normal(const fs::path& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal() : resolved;
}

// The nearest existing ancestor of `path` must be a folder, or nothing can be created under it.
void refuse_file_on_the_way(const std::string& option, const fs::path& path) {
  std::error_code error;
  for (fs::path up = fs::absolute(path).parent_path(); !up.empty(); up = up.parent_path()) {
    const fs::file_status status = fs::status(up, error);
    if (fs::exists(status)) {
      if (!fs::is_directory(status)) {
        throw BadInput(option + " " + path.string() + ": " + up.string() + " is a file, not a folder");
      }
      return;
    }
    if (up == up.root_path()) return;
  }
}

// What the commands write into a folder they replace (docs/outputs.md's table), and the endings of test's
// mismatch pictures: a folder that holds only these was written by an earlier version of this program.
constexpr std::array<std::string_view, 18> kOutputNames = {
    "report.json", "plan.json", "tree.png", "frames", "plan.mp4", "failed", "preview.png", "execution.json", "execution",
    "execution.mp4", "bench.json", "bench.png", "sweep.json", "sweep.png", "manifest.json", "units", "stderr.txt", "plan.actual.json"};
constexpr std::array<std::string_view, 3> kOutputEndings = {".actual.png", ".diff.png", ".log"};

// `name` less a ".tmp-<pid>" or ".old-<pid>" a killed writer left on it.
std::string without_leftover_tag(const std::string& name) {
  for (const std::string_view tag : {".tmp-", ".old-"}) {
    const std::size_t at = name.rfind(tag);
    if (at != std::string::npos && at > 0 && at + tag.size() < name.size() &&
        name.find_first_not_of("0123456789", at + tag.size()) == std::string::npos) {
      return name.substr(0, at);
    }
  }
  return name;
}

bool output_name(const std::string& written) {
  const std::string name = without_leftover_tag(written);
  if (name == kMadeHereMarker) return true;
  if (std::find(kOutputNames.begin(), kOutputNames.end(), name) != kOutputNames.end()) return true;
  return std::any_of(kOutputEndings.begin(), kOutputEndings.end(), [&](std::string_view ending) {
    return name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0;
  });
}

// Whether `inner` is `outer` or lies inside it, both normal.
bool within(const fs::path& inner, const fs::path& outer) {
  const auto [mismatch, unused] = std::mismatch(outer.begin(), outer.end(), inner.begin(), inner.end());
  return mismatch == outer.end();
}

// A name of at most 255 bytes (what file systems take) less room for the ".tmp-<pid>" of the temporary
// sibling every output is written as first.
constexpr std::size_t kMaxNameBytes = 240;

// Nothing is written into /proc or /sys, and no name is longer than kMaxNameBytes: said before any work,
// not after every test ran. By the path as written: /dev/stdout, a link into /proc, stays allowed.
void refuse_unwritable_path(const std::string& option, const fs::path& path) {
  const fs::path lexical = fs::absolute(path).lexically_normal();
  for (const char* system : {"/proc", "/sys"}) {
    if (within(lexical, system)) throw BadInput(option + " " + path.string() + ": lies in " + system + ", where nothing is written");
  }
  for (const fs::path& part : lexical) {
    if (part.string().size() > kMaxNameBytes) throw BadInput(option + " " + path.string() + ": holds a name over 240 bytes");
  }
}

}  // namespace

void check_folder_name(const fs::path& folder) {
  const std::string name = folder.filename().string();
  if (name.empty() || name == "." || name == ".." || name.size() > kMaxNameBytes) {
    throw BadInput("will not write " + folder.string() + ": '" + name +
                   "' is no folder name here (empty, '.', '..' or over 240 bytes; a scenario named so?)");
  }
  refuse_unwritable_path("will not write", folder);
}

void check_replaceable(const fs::path& folder, const std::vector<fs::path>& inputs) {
  check_folder_name(folder);
  const fs::path out = normal(folder);
  for (const fs::path& input : inputs) {
    const fs::path in = normal(input);
    if (within(in, out)) {
      throw BadInput("will not replace " + folder.string() + ": " + (in == out ? "it is " : "it holds ") + input.string() +
                     ", an input of this command; give another --out");
    }
  }
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
    throw BadInput("will not replace " + folder.string() + ": it is a file, not a folder of outputs");
  }
  if (!fs::is_directory(folder, error) || fs::exists(folder / kMadeHereMarker, error)) return;
  std::vector<std::string> foreign;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    if (!output_name(entry.path().filename().string())) foreign.push_back(entry.path().filename().string());
  }
  if (foreign.empty()) return;
  std::sort(foreign.begin(), foreign.end());
  std::string listed;
  for (std::size_t i = 0; i < std::min<std::size_t>(foreign.size(), 3); ++i) listed += (i ? ", " : "") + foreign[i];
  if (foreign.size() > 3) listed += " and " + std::to_string(foreign.size() - 3) + " more";
  throw BadInput("will not replace " + folder.string() + ": physltl-studio did not make it, and it holds " + listed +
                 "; give another --out, or empty the folder");
}

void mark_made_here(const fs::path& folder) {
  write_text_file(folder / kMadeHereMarker, "made by physltl-studio, which may replace this folder (docs/outputs.md)\n");
}

bool same_path(const fs::path& a, const fs::path& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  return normal(a) == normal(b);
}

fs::path checked_output_file(const std::string& option, const std::string& file, const std::vector<fs::path>& inputs) {
  if (file.empty()) throw BadInput(option + ": an empty path; give a file name");
  std::error_code error;
  if (fs::is_directory(file, error)) throw BadInput(option + " " + file + ": is a folder; give a file name");
  refuse_unwritable_path(option, file);
  for (const fs::path& input : inputs) {
    if (same_path(file, input)) {
      throw BadInput(option + " " + file + ": is " + input.string() + ", an input of this command; give another file");
    }
  }
  refuse_file_on_the_way(option, file);
  return file;
}

fs::path checked_output_folder(const std::string& option, const std::string& folder, const std::vector<fs::path>& inputs) {
  if (folder.empty()) throw BadInput(option + ": an empty path; give a folder");
  refuse_unwritable_path(option, folder);
  refuse_file_on_the_way(option, folder);
  std::error_code error;
  if (fs::exists(folder, error) && !fs::is_directory(folder, error)) {
    throw BadInput(option + " " + folder + ": is a file, not a folder");
  }
  const fs::path out = normal(folder);
  for (const fs::path& input : inputs) {
    const fs::path in = normal(input);
    const auto [mismatch, unused] = std::mismatch(in.begin(), in.end(), out.begin(), out.end());
    if (mismatch == in.end()) {
      throw BadInput(option + " " + folder + ": is " + (out == in ? "" : "inside ") + input.string() +
                     ", an input of this command; give another folder");
    }
  }
  return folder;
}

}  // namespace physltl::common
