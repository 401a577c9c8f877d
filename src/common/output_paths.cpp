#include "physltl/common/output_paths.h"

#include "physltl/common/bad_input.h"

#include <algorithm>

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

}  // namespace

bool same_path(const fs::path& a, const fs::path& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error);
  return normal(a) == normal(b);
}

fs::path checked_output_file(const std::string& option, const std::string& file, const std::vector<fs::path>& inputs) {
  if (file.empty()) throw BadInput(option + ": an empty path; give a file name");
  std::error_code error;
  if (fs::is_directory(file, error)) throw BadInput(option + " " + file + ": is a folder; give a file name");
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
