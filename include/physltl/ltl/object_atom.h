#pragma once
// Object propositions: an atom written BODY@REGION says "the centre of movable body BODY lies inside region
// REGION". The LTL layer knows only how such an atom is spelled; what it means is the World's business.
//
// Atoms without '@' are about the robot. The robot is in at most one region at a time and so is each body
// (regions are disjoint), which decides which letters can occur (src/ltl/exclusivity.h).

#include <optional>
#include <string>
#include <string_view>

namespace physltl::ltl {

struct ObjectAtom {
  std::string body;
  std::string region;
};

// The body and the region of an object atom; nothing for an atom about the robot. The parser refuses
// atoms with '@' at their start or end, or with more than one '@'.
std::optional<ObjectAtom> object_atom(std::string_view proposition);

}  // namespace physltl::ltl
