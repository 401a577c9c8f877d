#include "physltl/ltl/formula.h"

#include "physltl/ltl/object_atom.h"

#include <algorithm>
#include <cctype>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <unordered_set>

namespace physltl::ltl {

struct Formula::Node {
  Op op;
  Origin origin;
  std::string name;
  std::vector<Formula> children;
  std::size_t hash;
  std::size_t depth;
};

const char* spelling(Op op) {
  switch (op) {
    case Op::True: return "true";
    case Op::False: return "false";
    case Op::Atom: return "atom";
    case Op::Not: return "!";
    case Op::Next: return "X";
    case Op::Finally: return "F";
    case Op::Globally: return "G";
    case Op::And: return "&";
    case Op::Or: return "|";
    case Op::Xor: return "^";
    case Op::Implies: return "->";
    case Op::Equiv: return "<->";
    case Op::Until: return "U";
    case Op::Release: return "R";
    case Op::WeakUntil: return "W";
    case Op::StrongRelease: return "M";
  }
  return "?";
}

namespace {

std::size_t mix(std::size_t seed, std::size_t value) {
  return seed ^ (value + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2));
}

bool is_unary(Op op) { return op == Op::Not || op == Op::Next || op == Op::Finally || op == Op::Globally; }
bool is_nary(Op op) { return op == Op::And || op == Op::Or; }
bool is_binary(Op op) {
  return op == Op::Xor || op == Op::Implies || op == Op::Equiv || op == Op::Until || op == Op::Release ||
         op == Op::WeakUntil || op == Op::StrongRelease;
}

}  // namespace

Formula Formula::make(Op op, std::string name, std::vector<Formula> children, Origin origin) {
  std::size_t h = mix(static_cast<std::size_t>(op), std::hash<std::string>{}(name));
  std::size_t depth = 0;
  for (const Formula& c : children) {
    h = mix(h, c.hash());
    depth = std::max(depth, c.depth());
  }
  if (origin.column == 0) origin.written = op;
  return Formula(std::make_shared<const Node>(
      Node{op, origin, std::move(name), std::move(children), h, depth + 1}));
}

Formula Formula::tt() { return make(Op::True, {}, {}, {}); }
Formula Formula::ff() { return make(Op::False, {}, {}, {}); }

Formula Formula::atom(std::string name, Origin origin) {
  if (name.empty()) throw std::invalid_argument("an atomic proposition needs a name");
  for (unsigned char c : name)
    if (c == '"' || c < 0x20 || c == 0x7f)
      throw std::invalid_argument("an atomic proposition's name cannot contain '\"' or control characters");
  return make(Op::Atom, std::move(name), {}, origin);
}

Formula Formula::unary(Op op, Formula operand, Origin origin) {
  if (!is_unary(op)) throw std::invalid_argument(std::string(spelling(op)) + " is not a unary operator");
  return make(op, {}, {std::move(operand)}, origin);
}

Formula Formula::binary(Op op, Formula left, Formula right, Origin origin) {
  if (is_nary(op)) return nary(op, {std::move(left), std::move(right)}, origin);
  if (!is_binary(op)) throw std::invalid_argument(std::string(spelling(op)) + " is not a binary operator");
  return make(op, {}, {std::move(left), std::move(right)}, origin);
}

Formula Formula::nary(Op op, std::vector<Formula> operands, Origin origin) {
  if (!is_nary(op)) throw std::invalid_argument(std::string(spelling(op)) + " is not & or |");
  // The empty conjunction is true and the empty disjunction false; one operand stands for itself.
  if (operands.empty()) return op == Op::And ? tt() : ff();
  if (operands.size() == 1) return std::move(operands.front());
  std::vector<Formula> flat;
  flat.reserve(operands.size());
  for (Formula& f : operands) {
    if (f.op() == op)
      flat.insert(flat.end(), f.children().begin(), f.children().end());
    else
      flat.push_back(std::move(f));
  }
  return make(op, {}, std::move(flat), origin);
}

Op Formula::op() const { return node_->op; }
const std::string& Formula::name() const { return node_->name; }
std::span<const Formula> Formula::children() const { return node_->children; }
Origin Formula::origin() const { return node_->origin; }
std::size_t Formula::hash() const { return node_->hash; }
std::size_t Formula::depth() const { return node_->depth; }

bool operator==(const Formula& a, const Formula& b) {
  if (a.node_ == b.node_) return true;
  if (a.hash() != b.hash() || a.op() != b.op() || a.name() != b.name()) return false;
  return std::ranges::equal(a.children(), b.children());
}

std::strong_ordering operator<=>(const Formula& a, const Formula& b) {
  if (a.node_ == b.node_) return std::strong_ordering::equal;
  if (auto c = a.op() <=> b.op(); c != 0) return c;
  if (auto c = a.name() <=> b.name(); c != 0) return c;
  return std::lexicographical_compare_three_way(a.children().begin(), a.children().end(),
                                                b.children().begin(), b.children().end());
}

namespace {

// Binding strength for printing, as in Spot's grammar: higher binds tighter.
int precedence(Op op) {
  switch (op) {
    case Op::Implies:
    case Op::Equiv: return 1;
    case Op::Or: return 2;
    case Op::Xor: return 3;
    case Op::And: return 4;
    case Op::Until:
    case Op::Release:
    case Op::WeakUntil:
    case Op::StrongRelease: return 5;
    case Op::Not:
    case Op::Next:
    case Op::Finally:
    case Op::Globally: return 6;
    case Op::True:
    case Op::False:
    case Op::Atom: return 7;
  }
  return 7;
}

bool is_word(std::string_view name) {
  return !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_') &&
         std::ranges::all_of(name, [](char c) {
           unsigned char u = static_cast<unsigned char>(c);
           return u < 0x80 && (std::isalnum(u) || c == '_');
         });
}

// Names the parser reads back as the same atom without quotes: words with a lower-case start, clear of the
// operators U R W M and of Spot's rule that splits `GFa` into G(F(a)); and BODY@REGION of two words, which
// the parser reads whole before any splitting.
bool is_plain_name(const std::string& name) {
  if (const auto object = object_atom(name)) return is_word(object->body) && is_word(object->region);
  if (name == "true" || name == "false") return false;
  return (std::islower(static_cast<unsigned char>(name[0])) || name[0] == '_') && is_word(name);
}

bool is_boolean_binary(Op op) {
  return op == Op::And || op == Op::Or || op == Op::Xor || op == Op::Implies || op == Op::Equiv;
}

// Like Spot, parenthesise a Boolean connective inside another (`a | (b & c)`, `(a -> b) -> c`) even where
// precedence would not need it: nobody should have to remember that & binds tighter than |.
bool needs_parentheses(Op parent, const Formula& child, bool tighter_side) {
  const int pp = precedence(parent);
  const int cp = precedence(child.op());
  if (is_boolean_binary(parent) && is_boolean_binary(child.op())) return true;
  return tighter_side ? cp <= pp : cp < pp;
}

void print(std::string& out, const Formula& f);

void print_operand(std::string& out, const Formula& f, bool parenthesise) {
  if (parenthesise) out += '(';
  print(out, f);
  if (parenthesise) out += ')';
}

void print(std::string& out, const Formula& f) {
  const Op op = f.op();
  const int prec = precedence(op);
  switch (op) {
    case Op::True:
    case Op::False: out += spelling(op); return;
    case Op::Atom:
      if (is_plain_name(f.name()))
        out += f.name();
      else
        out += '"' + f.name() + '"';
      return;
    case Op::Not:
    case Op::Next:
    case Op::Finally:
    case Op::Globally: {
      out += spelling(op);
      const bool paren = precedence(f.child(0).op()) < prec;
      if (op != Op::Not && !paren) out += ' ';
      print_operand(out, f.child(0), paren);
      return;
    }
    case Op::And:
    case Op::Or:
      for (std::size_t i = 0; i < f.children().size(); ++i) {
        if (i > 0) out += op == Op::And ? " & " : " | ";
        print_operand(out, f.child(i), needs_parentheses(op, f.child(i), true));
      }
      return;
    default: {
      // Xor is left-associative; -> <-> U R W M are right-associative, as in Spot.
      const bool left_assoc = op == Op::Xor;
      print_operand(out, f.child(0), needs_parentheses(op, f.child(0), !left_assoc));
      out += ' ';
      out += spelling(op);
      out += ' ';
      print_operand(out, f.child(1), needs_parentheses(op, f.child(1), left_assoc));
      return;
    }
  }
}

void collect_propositions(const Formula& f, std::vector<std::string>& out,
                          std::unordered_set<std::string>& seen) {
  if (f.op() == Op::Atom) {
    if (seen.insert(f.name()).second) out.push_back(f.name());
    return;
  }
  for (const Formula& c : f.children()) collect_propositions(c, out, seen);
}

}  // namespace

std::string to_string(const Formula& f) {
  std::string out;
  print(out, f);
  return out;
}

std::ostream& operator<<(std::ostream& out, const Formula& f) { return out << to_string(f); }

std::vector<std::string> propositions(const Formula& f) {
  std::vector<std::string> out;
  std::unordered_set<std::string> seen;
  collect_propositions(f, out, seen);
  return out;
}

std::vector<std::string> avoided_propositions(const Formula& pnf) {
  std::vector<std::string> negated, positive;
  const auto note = [](std::vector<std::string>& list, const std::string& name) {
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  };
  const auto walk = [&](const auto& self, const Formula& f, bool both) -> void {
    if (f.op() == Op::Atom) {
      note(positive, f.name());
      if (both) note(negated, f.name());
      return;
    }
    if (f.op() == Op::Not && f.child(0).op() == Op::Atom) {
      note(negated, f.child(0).name());
      if (both) note(positive, f.child(0).name());
      return;
    }
    const bool self_dual = f.op() == Op::Equiv || f.op() == Op::Xor;
    for (const Formula& c : f.children()) self(self, c, both || self_dual);
  };
  walk(walk, pnf, false);
  std::vector<std::string> avoided;
  for (const std::string& name : negated) {
    if (std::find(positive.begin(), positive.end(), name) == positive.end()) avoided.push_back(name);
  }
  return avoided;
}

}  // namespace physltl::ltl
