#include "physltl/scenario/plan_cost.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <utility>

namespace physltl::scenario {
namespace {

// Weights are relative: a million to one says "only this term" already. Bounded, every cost a plan can
// have is finite and within what campaigns read back (unit_record.cpp: 10^15).
constexpr double kMaxWeight = 1e6;

struct Measure {
  const char* name;
  double PlanCost::*weight;
  const char* unit;
};
constexpr std::array<Measure, 4> kMeasures = {{{"time", &PlanCost::time, "s"},
                                               {"length", &PlanCost::length, "m"},
                                               {"pushes", &PlanCost::pushes, "pushes"},
                                               {"moved", &PlanCost::moved, "bodies"}}};

std::string weight_text(double w) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, w);
  return error == std::errc{} ? std::string(buffer, end) : std::to_string(w);
}

// The text's tokens: numbers, names, '+' and '*'.
class Tokens {
 public:
  explicit Tokens(std::string_view text) : text_(text) { skip_space(); }
  bool done() const { return at_ == text_.size(); }
  std::string_view peek() const {
    if (done()) return {};
    const char c = text_[at_];
    std::size_t end = at_ + 1;
    if (std::isalpha(static_cast<unsigned char>(c))) {
      while (end < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '_')) ++end;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == '-') {
      while (end < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[end])) || text_[end] == '.' ||
                                    ((text_[end] == '-' || text_[end] == '+') && (text_[end - 1] == 'e' || text_[end - 1] == 'E')))) {
        ++end;
      }
    }
    return text_.substr(at_, end - at_);
  }
  std::string_view next() {
    const std::string_view token = peek();
    at_ += token.size();
    skip_space();
    return token;
  }

 private:
  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }
  std::string_view text_;
  std::size_t at_ = 0;
};

[[noreturn]] void fail(std::string_view token, const std::string& why) {
  throw PlanCostError(token.empty() ? why + " at the end" : why + " at '" + std::string(token) + "'");
}

}  // namespace

PlanCost parse_plan_cost(std::string_view text) {
  PlanCost cost{0.0, 0.0, 0.0, 0.0};
  Tokens tokens(text);
  if (tokens.done()) throw PlanCostError("no cost given: name time, length, pushes or moved");
  std::array<bool, kMeasures.size()> named{};
  while (true) {
    double weight = 1.0;
    std::string_view token = tokens.next();
    if (!token.empty() && !std::isalpha(static_cast<unsigned char>(token[0]))) {
      const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), weight);
      if (error != std::errc{} || end != token.data() + token.size() || !(weight >= 0.0 && weight <= kMaxWeight)) {
        fail(token, "a weight must be a number from 0 to 1000000");
      }
      if (tokens.peek() == "*") tokens.next();
      token = tokens.next();
    }
    std::size_t m = 0;
    while (m < kMeasures.size() && token != kMeasures[m].name) ++m;
    if (m == kMeasures.size()) fail(token, "expected time, length, pushes or moved");
    if (named[m]) fail(token, std::string(kMeasures[m].name) + " is named twice");
    named[m] = true;
    cost.*kMeasures[m].weight = weight;
    if (tokens.done()) break;
    if (tokens.peek() != "+") fail(tokens.peek(), "expected '+' between terms");
    tokens.next();
  }
  if (cost.time + cost.length + cost.pushes + cost.moved == 0.0) throw PlanCostError("every weight is 0: nothing to lower");
  return cost;
}

std::string PlanCost::text() const {
  std::string out;
  for (const Measure& m : kMeasures) {
    const double w = this->*m.weight;
    if (w == 0.0) continue;
    if (!out.empty()) out += " + ";
    if (w != 1.0) out += weight_text(w) + " ";
    out += m.name;
  }
  return out;
}

std::string PlanCost::unit() const {
  std::string unit;
  int terms = 0;
  for (const Measure& m : kMeasures) {
    if (this->*m.weight == 0.0) continue;
    ++terms;
    unit = this->*m.weight == 1.0 ? m.unit : "";
  }
  return terms == 1 ? unit : "";
}

}  // namespace physltl::scenario
