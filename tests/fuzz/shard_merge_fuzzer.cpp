// libFuzzer target: the bytes are a shard of a campaign, its manifest.json and one unit result
// (units/0.json) separated by a line "----", as `bench merge` reads them back after a user, a full disk or
// another version had them. merge_shards must return the merged campaign or throw BadInput naming what is
// wrong; anything else (a crash, a sanitizer report, another exception, a hang, a huge allocation) is a bug.

#include "physltl/campaign/campaign.h"
#include "physltl/common/bad_input.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t separator = text.find("\n----\n");
  const fs::path shard = fs::path("/tmp/physltl-merge-fuzz-" + std::to_string(getpid())) / "shard-1-of-1";
  fs::remove_all(shard.parent_path());
  fs::create_directories(shard / "units");
  std::ofstream(shard / "manifest.json", std::ios::binary) << text.substr(0, separator);
  if (separator != std::string::npos) std::ofstream(shard / "units" / "0.json", std::ios::binary) << text.substr(separator + 6);
  try {
    physltl::campaign::merge_shards({shard.parent_path()});
  } catch (const physltl::common::BadInput&) {
  }
  return 0;
}
