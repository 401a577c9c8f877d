#include "physltl/common/fingerprint.h"

#include "physltl/common/bad_input.h"
#include "physltl/common/files.h"

#include <fmt/format.h>

namespace physltl::common {
namespace {

// A scenario and what it reads (modules, meshes): far below this.
constexpr std::size_t kMaxInputBytes = std::size_t{256} << 20;

}  // namespace

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::string file_fingerprint(const std::string& path) {
  return fmt::format("fnv1a64:{:016x}", fnv1a64(read_input_file(path, kMaxInputBytes)));
}

}  // namespace physltl::common
