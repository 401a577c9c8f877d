#include "physltl/ltl/object_atom.h"

namespace physltl::ltl {

std::optional<ObjectAtom> object_atom(std::string_view proposition) {
  const std::size_t at = proposition.find('@');
  if (at == std::string_view::npos) return std::nullopt;
  return ObjectAtom{std::string(proposition.substr(0, at)), std::string(proposition.substr(at + 1))};
}

}  // namespace physltl::ltl
