#pragma once
// What `physltl-studio test PATH...` tests: scenario files, folders of them, and entries with settings
// (`scenarios/rooms_n.lua::rooms=8`), as bench reads them.

#include <filesystem>
#include <string>
#include <vector>

namespace physltl::app::scenario_test {

struct TestEntry {
  std::string label;                    // as given: "scenarios/rooms_n.lua::rooms=8"
  std::filesystem::path file;
  std::vector<std::string> settings;    // key=value for the script's `params`
  std::string golden_name;              // "rooms_n" or "rooms_n.rooms=8": its goldens' folder
  std::string output_name;              // its folder under out/test/: golden_name, made unique by the path
};

// A folder stands for the .lua files directly in it, in name order. Throws BadInput for a path that is
// neither a .lua file nor a folder holding one, and for a setting that is not key=value. Entries of one
// golden name from different folders get output names apart.
std::vector<TestEntry> expand_test_paths(const std::vector<std::string>& paths);

}  // namespace physltl::app::scenario_test
