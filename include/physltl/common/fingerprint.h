#pragma once
// FNV-1a (64 bit): a stable hash of bytes, the same on every machine and build, for what a campaign must
// agree on across shards (the files a scenario was made from, the seed of the shard dealing) and for the
// determinism hash every build must give (docs/reliability.md). Not a defence against tampering: a check
// that nobody changed a file between shards by mistake.

#include <cstdint>
#include <string>
#include <string_view>

namespace physltl::common {

std::uint64_t fnv1a64(std::string_view bytes);

// "fnv1a64:<16 hex digits>" of the file's bytes; BadInput when it cannot be read.
std::string file_fingerprint(const std::string& path);

}  // namespace physltl::common
