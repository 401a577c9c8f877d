#include "physltl/common/printable.h"

#include <fmt/format.h>

namespace physltl::common {
namespace {

// The length of the well-formed UTF-8 sequence at text[i] that XML 1.0 allows, or 0.
std::size_t utf8_length(const std::string& text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  const std::size_t length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
  if (length == 0 || i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
  }
  const unsigned char second = length > 1 ? byte(i + 1) : 0;
  const bool overlong = (length == 2 && lead < 0xC2) || (length == 3 && lead == 0xE0 && second < 0xA0) ||
                        (length == 4 && lead == 0xF0 && second < 0x90);
  const bool surrogate = length == 3 && lead == 0xED && second >= 0xA0;
  const bool not_a_character = length == 3 && lead == 0xEF && second == 0xBF && byte(i + 2) >= 0xBE;  // U+FFFE/F
  const bool beyond_unicode = length == 4 && (lead > 0xF4 || (lead == 0xF4 && second >= 0x90));
  return overlong || surrogate || not_a_character || beyond_unicode ? 0 : length;
}

}  // namespace

std::string printable(const std::string& text) {
  std::string shown;
  shown.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::size_t length = utf8_length(text, i);
    if (c == '\t') {
      shown += "\\t";
    } else if (c == '\r') {
      shown += "\\r";
    } else if ((c < 0x20 && c != '\n') || c == 0x7F || length == 0) {
      shown += fmt::format("\\x{:02x}", c);
    } else {
      shown.append(text, i, length);
      i += length;
      continue;
    }
    ++i;
  }
  return shown;
}

}  // namespace physltl::common
