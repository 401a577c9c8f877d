// libFuzzer target: the bytes are a Sokoban level file, as `import sokoban FILE` reads one. The reader must
// return levels or throw BadInput; anything else (a crash, a sanitizer report, another exception, a hang)
// is a bug. And the importer writes only what `check` takes: every level within the limits the importer
// shares with the scenario reader (beyond_limits) becomes a scenario that the scenario reader accepts.

#include "physltl/common/bad_input.h"
#include "import/sokoban_level.h"
#include "import/sokoban_scenario.h"
#include "physltl/scenario/load.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace physltl::app;
  const std::string stem = "/tmp/physltl-sokoban-fuzz-" + std::to_string(getpid());
  std::ofstream(stem + ".txt", std::ios::binary).write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  std::vector<import::SokobanLevel> levels;
  try {
    levels = import::read_sokoban_levels(stem + ".txt");
  } catch (const common::BadInput&) {
    return 0;
  }
  for (const import::SokobanLevel& level : levels) {
    if (import::beyond_limits(level) || level.rows.size() * static_cast<std::size_t>(level.width()) > 400) continue;
    std::ofstream(stem + ".lua") << import::sokoban_scenario(level, "fuzz.txt", {});
    try {
      physltl::scenario::load_scenario(stem + ".lua");
    } catch (const physltl::scenario::ScenarioError& e) {
      std::fprintf(stderr, "an imported level that check refuses:\n%s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
