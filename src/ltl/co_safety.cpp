#include "physltl/ltl/co_safety.h"

namespace physltl::ltl {

namespace {

const char* reading(Op op) {
  switch (op) {
    case Op::Globally: return "G (always) constrains every position of the infinite run";
    case Op::Release: return "a R b (release) can require b forever, whenever a never comes";
    case Op::WeakUntil: return "a W b (weak until) is satisfied by a holding forever without b";
    case Op::Finally: return "F (eventually) has the negation G (always), which constrains the whole run";
    case Op::Until: return "U (until) has the negation R (release), which can require something forever";
    case Op::StrongRelease: return "M (strong release) has the negation W (weak until), satisfied only by a whole run";
    default: return "it is not allowed here";
  }
}

// Operands of <-> and ^ are needed with both polarities; these stay in the class when negated.
std::optional<CoSafetyViolation> find_in_self_dual(const Formula& f, Op context) {
  switch (f.op()) {
    case Op::True:
    case Op::False:
    case Op::Atom:
    case Op::Not:
      return std::nullopt;
    case Op::Next:
    case Op::And:
    case Op::Or:
    case Op::Xor:
    case Op::Equiv:
      for (const Formula& c : f.children())
        if (auto v = find_in_self_dual(c, context)) return v;
      return std::nullopt;
    default: return CoSafetyViolation{f.op(), f.origin(), context};
  }
}

std::optional<CoSafetyViolation> find(const Formula& f) {
  switch (f.op()) {
    case Op::Globally:
    case Op::Release:
    case Op::WeakUntil:
      return CoSafetyViolation{f.op(), f.origin(), Op::True};
    case Op::Xor:
    case Op::Equiv:
      for (const Formula& c : f.children())
        if (auto v = find_in_self_dual(c, f.op())) return v;
      return std::nullopt;
    case Op::Implies:  // PNF has none; any other caller gets a clear answer anyway
      return CoSafetyViolation{f.op(), f.origin(), Op::True};
    default:
      for (const Formula& c : f.children())
        if (auto v = find(c)) return v;
      return std::nullopt;
  }
}

}  // namespace

std::string CoSafetyViolation::message() const {
  const std::string where = origin.column > 0 ? " at column " + std::to_string(origin.column) : "";
  const std::string written = spelling(origin.column > 0 ? origin.written : op);
  std::string what;
  if (context != Op::True) {
    what = written + where + " is an operand of " + spelling(context) +
           ", which needs it both true and false; " + reading(op == origin.written ? op : origin.written);
  } else if (origin.column > 0 && origin.written != op) {
    what = written + where + " is negated (by ! or the left side of ->), so it is " + spelling(op) +
           " in positive normal form; " + reading(op);
  } else {
    what = written + where + ": " + reading(op);
  }
  return what;
}

std::optional<CoSafetyViolation> find_co_safety_violation(const Formula& pnf) { return find(pnf); }

}  // namespace physltl::ltl
