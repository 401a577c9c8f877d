// The determinism hash (docs/reliability.md, "Builds that agree"), in the manner of Box2D's: a fixed set of
// runs, one hash of the bytes they write. Every build gives the same value: CI builds and runs this suite
// with GCC 12 and with Clang 14, the runs below use one thread and two, and -O0 was measured by hand.

#include "command_runner.h"

#include "physltl/common/fingerprint.h"

#include <gtest/gtest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace {

using namespace physltl::testing_support;

// The value every build gives. A change that moves a plan or a frame changes it: the test then prints the
// new value, to be recorded here and in docs/reliability.md with the commit that changed it.
constexpr const char* kExpected = "42882a938d18d9b6";

// The files a run wrote under `folder` (plan.json and the frames; report.json holds clock readings), in
// name order.
std::vector<fs::path> hashed_files(const fs::path& folder) {
  std::vector<fs::path> files{folder / "plan.json"};
  if (fs::is_directory(folder / "frames")) {
    for (const auto& frame : fs::directory_iterator(folder / "frames")) files.push_back(frame.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

TEST(Determinism, TheFixedRunsWriteTheBytesEveryBuildWrites) {
  const fs::path out = fresh_out_dir();
  const fs::path ordered = small_ordered(test_dir("scenario"));
  struct FixedRun {
    std::string args, folder;
  };
  const std::vector<FixedRun> runs = {
      {ordered.string() + " --render --seed 5 --threads 1", "ordered"},  // pushes, and the frames
      {kSource + "/scenarios/delivery.lua --threads 2 --improve 200", "delivery"},  // a task about an object
      {kSource + "/scenarios/rooms_differential.lua --threads 2 --improve 200", "rooms_differential"},  // a differential drive
  };
  std::string bytes;
  for (const FixedRun& fixed : runs) {
    const Result r = run(fixed.args + " --quiet --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << fixed.args << ": " << r.err;
    for (const fs::path& file : hashed_files(out / fixed.folder)) {
      if (file.extension() != ".json") {
        bytes += slurp(file);
        continue;
      }
      nlohmann::json plan = nlohmann::json::parse(slurp(file));
      plan.erase("scenario");  // the scenario's path: the build folder's, not the build's
      bytes += plan.dump();
    }
  }
  EXPECT_EQ(fmt::format("{:016x}", physltl::common::fnv1a64(bytes)), kExpected)
      << "the fixed runs wrote other bytes: if a change meant to move these plans or frames, record the new "
         "value in tests/app/determinism_test.cpp and docs/reliability.md";
}

}  // namespace
