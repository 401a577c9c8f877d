// libFuzzer target: any bytes given to the parser must give a formula or a ParseError, never a crash,
// a sanitizer report or a hang; and every formula it accepts must print and parse back to itself.
// Short co-safe inputs also go through normal form, class check, both simplifications and translation.

#include "normal_form.h"
#include "physltl/ltl/parser.h"
#include "physltl/ltl/simplify.h"
#include "physltl/ltl/translate.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

namespace {

// Translation is exponential in the worst case (e.g. equivalences of many X formulas); keep the fuzzer
// on inputs where it must stay fast.
constexpr std::size_t kMaxTranslatedBytes = 40;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace physltl::ltl;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  Formula f = Formula::tt();
  try {
    f = parse(text);
  } catch (const ParseError&) {
    return 0;
  }
  if (!(parse(to_string(f)) == f)) std::abort();  // the printer must round-trip
  const Formula pnf = positive_normal_form(f);
  if (size > kMaxTranslatedBytes) return 0;
  const std::vector<std::string> props = propositions(pnf);
  const std::vector<std::string> invalid(props.begin(), props.begin() + static_cast<std::ptrdiff_t>(props.size() / 2));
  simplify_by_lists(pnf, invalid);
  const Simplification s = simplify_semantically(pnf, invalid);
  const Dfa dfa = translate(pnf);
  if (dfa.size() == 0 || dfa.start != 0) std::abort();
  if (s.formula) translate(*s.formula);
  return 0;
}
