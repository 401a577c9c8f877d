#include "test_entries.h"

#include "physltl/common/bad_input.h"

#include <algorithm>
#include <cctype>
#include <map>

namespace physltl::app::scenario_test {
namespace {

// Settings become part of a folder name: anything but letters, digits and ._=- turns into '_'.
std::string folder_safe(const std::string& text) {
  std::string safe = text;
  for (char& c : safe) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '=' || c == '-';
    if (!keep) c = '_';
  }
  return safe;
}

TestEntry parse_entry(const std::string& text) {
  TestEntry entry{text, {}, {}, {}, {}};
  std::size_t start = 0;
  std::size_t sep = text.find("::");
  entry.file = text.substr(0, sep);
  entry.golden_name = entry.file.stem().string();
  while (sep != std::string::npos) {
    start = sep + 2;
    sep = text.find("::", start);
    const std::string setting = text.substr(start, sep == std::string::npos ? std::string::npos : sep - start);
    if (setting.find('=') == std::string::npos || setting.front() == '=') {
      throw common::BadInput("'" + text + "': expected FILE::key=value::..., got the setting '" + setting + "'");
    }
    entry.settings.push_back(setting);
    entry.golden_name += "." + folder_safe(setting);
  }
  std::error_code error;
  if (!std::filesystem::exists(entry.file, error)) throw common::BadInput(entry.file.string() + ": no such file");
  if (entry.file.extension() != ".lua" || !std::filesystem::is_regular_file(entry.file, error)) {
    throw common::BadInput("'" + entry.file.string() + "' is not a scenario file (.lua)");
  }
  entry.output_name = entry.golden_name;
  return entry;
}

// Scenarios of one name in different folders would share out/test/<name>/: each such one's outputs go to
// a folder named after its path instead ("a/x/rooms.lua" -> "a_x_rooms").
void name_outputs_apart(std::vector<TestEntry>& entries) {
  std::map<std::string, int> count;
  for (const TestEntry& e : entries) ++count[e.golden_name];
  for (TestEntry& e : entries) {
    if (count[e.golden_name] < 2) continue;
    const std::string folder = e.file.parent_path().lexically_normal().string();
    e.output_name = folder_safe(folder.empty() || folder == "." ? "" : folder + "/") + e.golden_name;
  }
}

}  // namespace

std::vector<TestEntry> expand_test_paths(const std::vector<std::string>& paths) {
  std::vector<TestEntry> entries;
  for (const std::string& path : paths) {
    if (path.find("::") == std::string::npos && std::filesystem::is_directory(path)) {
      std::vector<std::filesystem::path> files;
      for (const auto& item : std::filesystem::directory_iterator(path)) {
        if (item.is_regular_file() && item.path().extension() == ".lua") files.push_back(item.path());
      }
      if (files.empty()) throw common::BadInput("'" + path + "' holds no scenario file (.lua)");
      std::sort(files.begin(), files.end());
      for (const auto& file : files) entries.push_back(parse_entry(file.string()));
    } else {
      entries.push_back(parse_entry(path));
    }
  }
  name_outputs_apart(entries);
  return entries;
}

}  // namespace physltl::app::scenario_test
