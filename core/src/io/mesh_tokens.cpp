// convexloc — the token helpers the text mesh readers share.
#include <charconv>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "io/mesh_tokens.hpp"

namespace convexloc::detail {

std::string quote(std::string_view s) {
  std::string out = "'";
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (i == 24) {
      out += "...";
      break;
    }
    unsigned char u = static_cast<unsigned char>(s[i]);
    out += (u >= 0x20 && u < 0x7f) ? s[i] : '?';
  }
  return out + "'";
}

double number(std::string_view token, std::size_t line) {
  // a token of a format without comments may hold a '#', which parseRow would skip
  if (token.find('#') != std::string_view::npos)
    throw ParseError("not a number: " + quote(token), line);
  double v = 0;
  parseRow(token, line, 1, &v);
  return v;
}

bool integer(std::string_view token, long long& out) {
  if (token.empty()) return false;
  const char* b = token.data();
  if (*b == '+') ++b;
  auto [ptr, ec] = std::from_chars(b, token.data() + token.size(), out);
  return ec == std::errc() && ptr == token.data() + token.size() &&
         b != token.data() + token.size();
}

Vec3 coordinates(Tokens& t, std::size_t line) {
  std::string_view tok;
  double xyz[3];
  for (double& c : xyz) {
    if (!t.next(tok)) throw ParseError("a vertex needs 3 coordinates", line);
    c = number(tok, line);
  }
  return {xyz[0], xyz[1], xyz[2]};
}

void numbersOnly(Tokens& t, std::size_t line) {
  std::string_view tok;
  while (t.next(tok)) number(tok, line);
}

}  // namespace convexloc::detail
