#include "fingerprint.h"

#include "common/bad_input.h"

#include <fmt/format.h>

#include <fstream>
#include <iterator>

namespace physltl::app {

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325ull;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::string file_fingerprint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BadInput("cannot read " + path);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return fmt::format("fnv1a64:{:016x}", fnv1a64(bytes));
}

}  // namespace physltl::app
