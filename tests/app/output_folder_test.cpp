// OutputFolder: outputs appear whole at commit, and the previous ones survive anything short of it.

#include "physltl/common/output_folder.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/output_paths.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <stdexcept>

namespace physltl::common {
namespace {

namespace fs = std::filesystem;

class OutputFolderTest : public testing::Test {
 protected:
  void SetUp() override {
    parent_ = fs::path(PHYSLTL_TEST_OUTPUT_DIR) / "output_folder" / testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(parent_);
    fs::create_directories(parent_);
    final_ = parent_ / "rooms";
  }

  static void write(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }
  static std::string read(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  static std::set<std::string> names_in(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(folder)) names.insert(e.path().filename().string());
    return names;
  }

  fs::path parent_, final_;
};

TEST_F(OutputFolderTest, WritesBesideTheFinalFolderAndNothingAppearsUntilCommit) {
  {
    OutputFolder folder(final_, OutputFolder::Commit::kWhole);
    EXPECT_EQ(folder.path().parent_path(), parent_);
    EXPECT_TRUE(fs::is_directory(folder.path()));
    write(folder.path() / "preview.png", "new");
    EXPECT_FALSE(fs::exists(final_));
  }
  EXPECT_TRUE(names_in(parent_).empty()) << "the uncommitted temporary folder must be gone";
}

TEST_F(OutputFolderTest, AFailedRunLeavesThePreviousOutputsAsTheyWere) {
  fs::create_directory(final_);
  write(final_ / "plan.mp4", "old plan");
  try {
    OutputFolder folder(final_, OutputFolder::Commit::kWhole);
    write(folder.path() / "plan.mp4", "half a plan");
    throw std::runtime_error("planning failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(names_in(parent_), std::set<std::string>{"rooms"});
  EXPECT_EQ(read(final_ / "plan.mp4"), "old plan");
}

TEST_F(OutputFolderTest, CommitReplacesThePreviousFolderWhole) {
  fs::create_directories(final_ / "frames");
  write(final_ / "frames" / "frame_00000.png", "old frame");
  write(final_ / "tree.png", "old tree");
  OutputFolder folder(final_, OutputFolder::Commit::kWhole);
  write(folder.path() / "tree.png", "new tree");
  folder.commit();
  EXPECT_EQ(names_in(parent_), std::set<std::string>{"rooms"}) << "no temporary or old folder left behind";
  EXPECT_EQ(names_in(final_), (std::set<std::string>{kMadeHereMarker, "tree.png"}));
  EXPECT_EQ(read(final_ / "tree.png"), "new tree");
}

TEST_F(OutputFolderTest, CommitEntriesReplacesOnlyWhatWasWritten) {
  fs::create_directory(final_);
  write(final_ / "plan.mp4", "a plan");
  write(final_ / "preview.png", "old preview");
  OutputFolder folder(final_, OutputFolder::Commit::kEntries);
  write(folder.path() / "preview.png", "new preview");
  folder.commit();
  EXPECT_EQ(names_in(parent_), std::set<std::string>{"rooms"});
  EXPECT_EQ(names_in(final_), (std::set<std::string>{"plan.mp4", "preview.png"}));
  EXPECT_EQ(read(final_ / "plan.mp4"), "a plan");
  EXPECT_EQ(read(final_ / "preview.png"), "new preview");
}

TEST_F(OutputFolderTest, CommitEntriesCreatesTheFinalFolderWhenThereIsNone) {
  OutputFolder folder(parent_ / "out" / "rooms", OutputFolder::Commit::kEntries);  // parents created as needed
  write(folder.path() / "preview.png", "new preview");
  folder.commit();
  EXPECT_EQ(names_in(parent_ / "out"), std::set<std::string>{"rooms"});
  EXPECT_EQ(read(parent_ / "out" / "rooms" / "preview.png"), "new preview");
}

TEST_F(OutputFolderTest, ATrailingSlashNamesTheSameFolder) {
  OutputFolder folder(final_.string() + "/", OutputFolder::Commit::kWhole);
  EXPECT_EQ(folder.final_path(), final_);
  EXPECT_EQ(folder.path().parent_path(), parent_);
}

// The rule for a folder replaced whole (docs/outputs.md): never one this program did not make that holds
// anything but output names, never one holding an input, never one named "." or ".."; one it made (the
// marker inside) is replaced whatever else it holds, and one of an earlier version's outputs too.
TEST_F(OutputFolderTest, AFolderReplacedWholeMustBeOneThisProgramMadeAndHoldNoInput) {
  fs::create_directory(final_);
  write(final_ / "plan.json", "an earlier version's plan");
  write(final_ / "rooms.lua", "the user's scenario");
  write(final_ / "notes.txt", "the user's notes");
  try {
    OutputFolder refused(final_, OutputFolder::Commit::kWhole);
    ADD_FAILURE() << "a folder of the user's files was taken";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("physltl-studio did not make it, and it holds notes.txt, rooms.lua"), std::string::npos) << e.what();
  }
  write(final_ / kMadeHereMarker, "");
  try {
    OutputFolder refused(final_, OutputFolder::Commit::kWhole, {final_ / "rooms.lua"});
    ADD_FAILURE() << "a folder holding an input was taken";
  } catch (const BadInput& e) {
    EXPECT_NE(std::string(e.what()).find("it holds " + (final_ / "rooms.lua").string() + ", an input of this command"),
              std::string::npos) << e.what();
  }
  EXPECT_EQ(names_in(final_), (std::set<std::string>{kMadeHereMarker, "notes.txt", "plan.json", "rooms.lua"}));
  {
    OutputFolder marked(final_, OutputFolder::Commit::kWhole);  // made here: replaced
    marked.commit();
  }
  EXPECT_EQ(names_in(final_), std::set<std::string>{kMadeHereMarker});
  fs::remove(final_ / kMadeHereMarker);
  write(final_ / "report.json", "an earlier version's report");
  EXPECT_NO_THROW(OutputFolder(final_, OutputFolder::Commit::kWhole));  // output names only
  for (const std::string name : {".", ".."}) {
    EXPECT_THROW(OutputFolder(parent_ / "out" / name, OutputFolder::Commit::kWhole), BadInput) << name;
    EXPECT_THROW(check_folder_name(parent_ / "out" / name), BadInput) << name;
  }
  EXPECT_NO_THROW(OutputFolder(".", OutputFolder::Commit::kEntries));  // import --out . adds files to the working folder
  EXPECT_THROW(OutputFolder("/proc/self/rooms", OutputFolder::Commit::kWhole), BadInput);
}

}  // namespace
}  // namespace physltl::common
