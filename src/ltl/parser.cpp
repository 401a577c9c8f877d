#include "physltl/ltl/parser.h"

#include <array>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

namespace physltl::ltl {

ParseError::ParseError(std::uint32_t column, const std::string& message)
    : std::runtime_error("column " + std::to_string(column) + ": " + message), column_(column) {}

namespace {

enum class Tok { Atom, True, False, Unary, Binary, LParen, RParen, End };

struct Token {
  Tok kind;
  Op op = Op::True;      // for Unary and Binary
  std::string name;      // for Atom
  std::string_view text;  // as written, for messages
  std::uint32_t column;
};

bool is_word_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool is_word_char(char c) { return is_word_start(c) || (c >= '0' && c <= '9'); }

// Multi-byte UTF-8 symbols and the operators they stand for.
struct Symbol {
  std::string_view utf8;
  Tok kind;
  Op op;
};
constexpr std::array<Symbol, 8> kSymbols{{
    {"\u25C7", Tok::Unary, Op::Finally},   // ◇
    {"\u25A1", Tok::Unary, Op::Globally},  // □
    {"\u25CB", Tok::Unary, Op::Next},      // ○
    {"\u00AC", Tok::Unary, Op::Not},       // ¬
    {"\u2227", Tok::Binary, Op::And},      // ∧
    {"\u2228", Tok::Binary, Op::Or},       // ∨
    {"\u2192", Tok::Binary, Op::Implies},  // →
    {"\u2194", Tok::Binary, Op::Equiv},    // ↔
}};

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  // Splitting `GFa` yields several tokens from one word; they wait here.
  std::vector<Token> next() {
    skip_space();
    const std::size_t start = pos_;
    const std::uint32_t column = column_;
    if (pos_ == text_.size()) return {Token{Tok::End, Op::True, {}, {}, column}};
    const char c = text_[pos_];
    auto single = [&](Tok kind, Op op, std::size_t length) {
      advance(length);
      return std::vector<Token>{Token{kind, op, {}, text_.substr(start, length), column}};
    };
    auto starts = [&](std::string_view s) { return text_.substr(pos_).starts_with(s); };

    if (c == '(') return single(Tok::LParen, Op::True, 1);
    if (c == ')') return single(Tok::RParen, Op::True, 1);
    if (c == '!') return single(Tok::Unary, Op::Not, 1);
    if (starts("&&")) return single(Tok::Binary, Op::And, 2);
    if (c == '&') return single(Tok::Binary, Op::And, 1);
    if (starts("||")) return single(Tok::Binary, Op::Or, 2);
    if (c == '|') return single(Tok::Binary, Op::Or, 1);
    if (c == '^') return single(Tok::Binary, Op::Xor, 1);
    if (starts("->") || starts("=>")) return single(Tok::Binary, Op::Implies, 2);
    if (starts("<->") || starts("<=>")) return single(Tok::Binary, Op::Equiv, 3);
    if (starts("<>")) return single(Tok::Unary, Op::Finally, 2);
    if (starts("[]")) return single(Tok::Unary, Op::Globally, 2);
    for (const Symbol& s : kSymbols)
      if (starts(s.utf8)) return single(s.kind, s.op, s.utf8.size());
    if (c == '"') return {quoted(column)};
    if (c >= '0' && c <= '9') return {number(column)};
    if (is_word_start(c)) return word(column);
    if (c == '-' || c == '=' || c == '<')
      throw ParseError(column, "expected '->', '=>', '<->', '<=>' or '<>' but found " + describe_here());
    throw ParseError(column, "unexpected " + describe_here());
  }

 private:
  void advance(std::size_t bytes) {
    for (std::size_t i = 0; i < bytes && pos_ < text_.size(); ++i, ++pos_)
      if ((static_cast<unsigned char>(text_[pos_]) & 0xC0) != 0x80) ++column_;  // count characters, not bytes
  }

  void skip_space() {
    while (pos_ < text_.size() &&
           (text_[pos_] == ' ' || text_[pos_] == '\t' || text_[pos_] == '\n' || text_[pos_] == '\r'))
      advance(1);
  }

  // The character at the current position, printable whatever it is.
  std::string describe_here() const {
    const unsigned char c = static_cast<unsigned char>(text_[pos_]);
    if (c >= 0x20 && c < 0x7f) return std::string("'") + static_cast<char>(c) + "'";
    std::size_t length = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 1;
    bool valid = c >= 0xC2 && c <= 0xF4 && pos_ + length <= text_.size();
    for (std::size_t i = 1; valid && i < length; ++i)
      valid = (static_cast<unsigned char>(text_[pos_ + i]) & 0xC0) == 0x80;
    if (valid) return "'" + std::string(text_.substr(pos_, length)) + "'";
    char hex[32];
    std::snprintf(hex, sizeof hex, "byte 0x%02X", c);
    return hex;
  }

  Token quoted(std::uint32_t column) {
    const std::size_t start = pos_;
    advance(1);
    const std::size_t name_start = pos_;
    while (pos_ < text_.size() && text_[pos_] != '"') {
      const unsigned char c = static_cast<unsigned char>(text_[pos_]);
      if (c < 0x20 || c == 0x7f) throw ParseError(column_, "a quoted atom cannot contain control characters");
      advance(1);
    }
    if (pos_ == text_.size())
      throw ParseError(column, "expected '\"' to close the atom opened here, but the formula ended");
    std::string name(text_.substr(name_start, pos_ - name_start));
    advance(1);
    if (name.empty()) throw ParseError(column, "expected a name between the quotes");
    check_object_atom(name, column);
    return Token{Tok::Atom, Op::Atom, std::move(name), text_.substr(start, pos_ - start), column};
  }

  Token number(std::uint32_t column) {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_word_char(text_[pos_])) advance(1);
    const std::string_view w = text_.substr(start, pos_ - start);
    if (w == "1") return Token{Tok::True, Op::True, {}, w, column};
    if (w == "0") return Token{Tok::False, Op::False, {}, w, column};
    throw ParseError(column, "expected 0, 1 or a name starting with a letter, but found '" + std::string(w) +
                                 "' (quote it to use it as a name)");
  }

  // A body and a region: "crate@dock" and `crate@dock` are the same atom.
  static void check_object_atom(std::string_view name, std::uint32_t column) {
    const std::size_t at = name.find('@');
    if (at == std::string_view::npos) return;
    if (at == 0) throw ParseError(column, "expected a body's name before '@' in '" + std::string(name) + "'");
    if (at + 1 == name.size()) throw ParseError(column, "expected a region's name after '@' in '" + std::string(name) + "'");
    if (name.find('@', at + 1) != std::string_view::npos)
      throw ParseError(column, "an atom names one body and one region (BODY@REGION), but '" + std::string(name) +
                                   "' holds '@' twice");
  }

  std::vector<Token> word(std::uint32_t column) {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && is_word_char(text_[pos_])) advance(1);
    // BODY@REGION is one atom, read before any splitting: `Fridge@kitchen` is the fridge, not F(ridge@kitchen).
    if (pos_ < text_.size() && text_[pos_] == '@') {
      advance(1);
      if (pos_ == text_.size() || !is_word_start(text_[pos_]))
        throw ParseError(column_, "expected a region's name after '@', but found " +
                                      (pos_ == text_.size() ? std::string("the end") : describe_here()));
      while (pos_ < text_.size() && is_word_char(text_[pos_])) advance(1);
      if (pos_ < text_.size() && text_[pos_] == '@')
        throw ParseError(column_, "an atom names one body and one region (BODY@REGION), but this one holds '@' twice");
      const std::string_view atom = text_.substr(start, pos_ - start);
      return {Token{Tok::Atom, Op::Atom, std::string(atom), atom, column}};
    }
    const std::string_view w = text_.substr(start, pos_ - start);
    if (auto t = keyword(w, column)) return {*t};
    // Spot's convention: `GFa` is G(F(a)) and `Xp1` is X(p1); the rest must start in lower case.
    std::size_t prefix = 0;
    while (prefix < w.size() && (w[prefix] == 'F' || w[prefix] == 'G' || w[prefix] == 'X')) ++prefix;
    const bool split = prefix > 0 && prefix < w.size() && ((w[prefix] >= 'a' && w[prefix] <= 'z') || w[prefix] == '_');
    if (!split) return {Token{Tok::Atom, Op::Atom, std::string(w), w, column}};
    std::vector<Token> tokens;
    for (std::size_t i = 0; i < prefix; ++i)
      tokens.push_back(*keyword(w.substr(i, 1), column + static_cast<std::uint32_t>(i)));
    const std::string_view rest = w.substr(prefix);
    const std::uint32_t rest_column = column + static_cast<std::uint32_t>(prefix);
    if (auto t = keyword(rest, rest_column))
      tokens.push_back(*t);
    else
      tokens.push_back(Token{Tok::Atom, Op::Atom, std::string(rest), rest, rest_column});
    return tokens;
  }

  static std::optional<Token> keyword(std::string_view w, std::uint32_t column) {
    auto t = [&](Tok kind, Op op) { return Token{kind, op, {}, w, column}; };
    if (w == "true") return t(Tok::True, Op::True);
    if (w == "false") return t(Tok::False, Op::False);
    if (w.size() != 1) return std::nullopt;
    switch (w[0]) {
      case 'X': return t(Tok::Unary, Op::Next);
      case 'F': return t(Tok::Unary, Op::Finally);
      case 'G': return t(Tok::Unary, Op::Globally);
      case 'U': return t(Tok::Binary, Op::Until);
      case 'R': return t(Tok::Binary, Op::Release);
      case 'W': return t(Tok::Binary, Op::WeakUntil);
      case 'M': return t(Tok::Binary, Op::StrongRelease);
      default: return std::nullopt;
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::uint32_t column_ = 1;
};

// Precedence climbing over Spot's levels. Chains of one level are gathered in a loop and folded, so
// recursion only happens for parentheses, whose depth is bounded.
class Parser {
 public:
  explicit Parser(std::string_view text) : lexer_(text) { fill(); }

  Formula formula() {
    Formula f = implication();
    if (peek().kind == Tok::RParen) throw ParseError(peek().column, "found ')' with no matching '('");
    if (peek().kind != Tok::End)
      throw ParseError(peek().column, "expected a binary operator or the end of the formula, but found " +
                                          describe(peek()));
    return f;
  }

 private:
  enum Level { kImplies, kOr, kXor, kAnd, kUntil };

  static Level level_of(Op op) {
    switch (op) {
      case Op::Implies:
      case Op::Equiv: return kImplies;
      case Op::Or: return kOr;
      case Op::Xor: return kXor;
      case Op::And: return kAnd;
      default: return kUntil;
    }
  }

  const Token& peek() const { return pending_.front(); }
  Token take() {
    Token t = std::move(pending_.front());
    pending_.erase(pending_.begin());
    if (pending_.empty()) fill();
    return t;
  }
  void fill() {
    for (Token& t : lexer_.next()) pending_.push_back(std::move(t));
  }
  bool at_binary(Level level) const {
    return peek().kind == Tok::Binary && level_of(peek().op) == level;
  }

  static std::string describe(const Token& t) {
    switch (t.kind) {
      case Tok::End: return "the end of the formula";
      case Tok::Atom: return "the atomic proposition '" + std::string(t.text) + "'";
      default: return "'" + std::string(t.text) + "'";
    }
  }

  static Formula checked(Formula f, std::uint32_t column) {
    if (f.depth() > kMaxFormulaDepth)
      throw ParseError(column, "the formula is nested more than " + std::to_string(kMaxFormulaDepth) +
                                   " levels deep");
    return f;
  }

  // a -> b <-> c is a -> (b <-> c): right-associative.
  Formula implication() {
    std::vector<Formula> operands{nary_or()};
    std::vector<Token> ops;
    while (at_binary(kImplies)) {
      ops.push_back(take());
      operands.push_back(nary_or());
    }
    return fold_right(std::move(operands), ops);
  }

  Formula nary_or() {
    std::vector<Formula> operands{xor_chain()};
    std::optional<std::uint32_t> column;
    while (at_binary(kOr)) {
      if (!column) column = peek().column;
      take();
      operands.push_back(xor_chain());
    }
    if (!column) return std::move(operands.front());
    return Formula::nary(Op::Or, std::move(operands), Origin{*column, Op::Or});
  }

  // a ^ b ^ c is (a ^ b) ^ c: left-associative.
  Formula xor_chain() {
    Formula left = nary_and();
    while (at_binary(kXor)) {
      const Token op = take();
      left = checked(Formula::binary(Op::Xor, left, nary_and(), Origin{op.column, Op::Xor}), op.column);
    }
    return left;
  }

  Formula nary_and() {
    std::vector<Formula> operands{until_chain()};
    std::optional<std::uint32_t> column;
    while (at_binary(kAnd)) {
      if (!column) column = peek().column;
      take();
      operands.push_back(until_chain());
    }
    if (!column) return std::move(operands.front());
    return Formula::nary(Op::And, std::move(operands), Origin{*column, Op::And});
  }

  Formula until_chain() {
    std::vector<Formula> operands{unary()};
    std::vector<Token> ops;
    while (at_binary(kUntil)) {
      ops.push_back(take());
      operands.push_back(unary());
    }
    return fold_right(std::move(operands), ops);
  }

  static Formula fold_right(std::vector<Formula> operands, const std::vector<Token>& ops) {
    Formula right = std::move(operands.back());
    for (std::size_t i = ops.size(); i-- > 0;)
      right = checked(Formula::binary(ops[i].op, std::move(operands[i]), std::move(right),
                                      Origin{ops[i].column, ops[i].op}),
                      ops[i].column);
    return right;
  }

  Formula unary() {
    std::vector<Token> ops;
    while (peek().kind == Tok::Unary) ops.push_back(take());
    Formula f = primary();
    for (std::size_t i = ops.size(); i-- > 0;)
      f = checked(Formula::unary(ops[i].op, std::move(f), Origin{ops[i].column, ops[i].op}), ops[i].column);
    return f;
  }

  Formula primary() {
    const Token& t = peek();
    switch (t.kind) {
      case Tok::True: take(); return Formula::tt();
      case Tok::False: take(); return Formula::ff();
      case Tok::Atom: {
        Token a = take();
        return Formula::atom(std::move(a.name), Origin{a.column, Op::Atom});
      }
      case Tok::LParen: {
        const std::uint32_t open = take().column;
        if (++nesting_ > kMaxFormulaDepth)
          throw ParseError(open, "the formula is nested more than " + std::to_string(kMaxFormulaDepth) +
                                     " levels deep");
        Formula f = implication();
        if (peek().kind != Tok::RParen)
          throw ParseError(peek().column, "expected ')' to close the '(' at column " + std::to_string(open) +
                                              ", but found " + describe(peek()));
        take();
        --nesting_;
        return f;
      }
      default:
        throw ParseError(t.column,
                         "expected a formula (an atomic proposition, true, false, '(' or one of ! X F G), but "
                         "found " +
                             describe(t));
    }
  }

  Lexer lexer_;
  std::vector<Token> pending_;
  std::size_t nesting_ = 0;
};

}  // namespace

Formula parse(std::string_view text) { return Parser(text).formula(); }

}  // namespace physltl::ltl
