#pragma once
// Text from the user's input (a file name, a Lua error, a Sokoban row) as it may be shown: on a terminal,
// where a raw ESC or CR would rewrite what is printed, and in a JUnit XML report, where XML 1.0 has no way
// to write most control characters at all (a CI server rejects the whole file).

#include <string>

namespace physltl::common {

// `text` with every control character but the newline, and every byte that is not part of well-formed
// UTF-8, written as \xNN (a tab as \t, a CR as \r).
std::string printable(const std::string& text);

}  // namespace physltl::common
