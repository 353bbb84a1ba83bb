// convexloc (internal) — the tokens every text mesh reader (OFF, OBJ, ASCII STL and PLY)
// splits its lines into, and the numbers it reads from them, by the point files' rules.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "convexloc/geometry.hpp"
#include "io/text_scan.hpp"

namespace convexloc::detail {

// a short, printable quote of a token, for messages
std::string quote(std::string_view s);

// a decimal number, by the point-file rules (ParseError naming `line` otherwise)
double number(std::string_view token, std::size_t line);

// a whole token as a signed integer; false when it is not one
bool integer(std::string_view token, long long& out);

// the whitespace-separated tokens of a line, up to a '#' comment (`hashComments`)
class Tokens {
 public:
  explicit Tokens(std::string_view line, bool hashComments = true)
      : rest_(line), hash_(hashComments) {}
  // the next token; false at the end of the line (or at a comment)
  bool next(std::string_view& token) {
    std::size_t i = 0;
    while (i < rest_.size() && isBlank(rest_[i])) ++i;
    if (i == rest_.size() || (hash_ && rest_[i] == '#')) {
      rest_ = {};
      return false;
    }
    std::size_t j = i;
    while (j < rest_.size() && !isBlank(rest_[j]) && !(hash_ && rest_[j] == '#')) ++j;
    token = rest_.substr(i, j - i);
    rest_.remove_prefix(j);
    return true;
  }
  // every remaining token
  std::size_t count() const {
    Tokens copy = *this;
    std::string_view t;
    std::size_t n = 0;
    while (copy.next(t)) ++n;
    return n;
  }
  // the text not yet split, blanks included
  std::string_view rest() const noexcept { return rest_; }

 private:
  std::string_view rest_;
  bool hash_;
};

// "x y z": the next three tokens of `t` as a point (ParseError naming `line` otherwise)
Vec3 coordinates(Tokens& t, std::size_t line);

// every token left in `t` must be a number
void numbersOnly(Tokens& t, std::size_t line);

}  // namespace convexloc::detail
