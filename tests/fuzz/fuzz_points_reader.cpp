// Fuzz target: RowReader over arbitrary bytes, checked line by line against a reference.
//
// Byte 0 picks 2 or 3 numbers per row; the rest is the file. The reference below is written
// from the README's grammar, independently of core: a line is blank, a comment, or `dims`
// decimals separated by whitespace and/or one comma, with an optional '#' comment after;
// '\r' may end it. RowReader must return exactly the data lines the reference accepts, in
// order and with their line numbers, each number the double C's strtod gives, and must
// throw ParseError naming the first line the reference rejects.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace fuzz;

bool blank(char c) {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}
bool digit(char c) {
  return c >= '0' && c <= '9';
}

// length of the decimal at the start of s ([+-]? (d+ (. d*)? | . d+) ([eE] [+-]? d+)?), 0 if none
std::size_t decimalLength(std::string_view s) {
  std::size_t i = 0;
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t intDigits = 0, fracDigits = 0;
  while (i < s.size() && digit(s[i])) ++i, ++intDigits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && digit(s[i])) ++i, ++fracDigits;
  }
  if (intDigits + fracDigits == 0) return 0;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
    std::size_t expDigits = 0;
    while (j < s.size() && digit(s[j])) ++j, ++expDigits;
    if (expDigits > 0) i = j;
  }
  return i;
}

// The reference reading of one line (without its '\n'): false when it is malformed;
// otherwise `values` holds its numbers (none for a blank or comment line).
bool referenceRow(std::string_view line, std::vector<double>& values) {
  values.clear();
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::size_t i = 0;
  auto skipBlanks = [&] {
    std::size_t from = i;
    while (i < line.size() && blank(line[i])) ++i;
    return i > from;
  };
  auto atEnd = [&] { return i == line.size() || line[i] == '#'; };
  skipBlanks();
  if (atEnd()) return true;
  for (;;) {
    std::size_t len = decimalLength(line.substr(i));
    if (len == 0) return false;
    std::size_t end = i + len;
    if (end < line.size() && !blank(line[end]) && line[end] != ',' && line[end] != '#')
      return false;
    std::string token(line.substr(i, len));
    char* stop = nullptr;
    double v = std::strtod(token.c_str(), &stop);
    if (stop != token.c_str() + token.size()) fail("reference: strtod stopped early on " + token);
    if (std::isinf(v)) return false;  // out of the range of double
    values.push_back(v);
    i = end;
    bool separated = skipBlanks();
    if (atEnd()) return true;
    if (line[i] == ',') {
      ++i;
      skipBlanks();
      if (atEnd()) return false;  // a comma with no number after it
      separated = true;
    }
    if (!separated) return false;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const int dims = 2 + (data[0] & 1);
  ++data;
  --size;
  std::string_view text(reinterpret_cast<const char*>(data), size);

  // the reference: every line, in order, up to the first malformed one
  struct Row {
    std::size_t line;
    std::vector<double> values;
  };
  std::vector<Row> expected;
  std::size_t badLine = 0;  // 0: none
  std::size_t lineNo = 0;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t nl = text.find('\n', start);
    std::size_t end = nl == std::string_view::npos ? text.size() : nl;
    ++lineNo;
    std::vector<double> values;
    if (!referenceRow(text.substr(start, end - start), values) ||
        (!values.empty() && values.size() != static_cast<std::size_t>(dims))) {
      badLine = lineNo;
      break;
    }
    if (!values.empty()) expected.push_back({lineNo, values});
    start = end + 1;
  }

  MemFile file(data, size);
  convexloc::RowReader reader(file.get(), dims);
  std::size_t got = 0;
  double row[3];
  try {
    while (reader.next(row)) {
      if (got == expected.size())
        fail("RowReader returned a row at line " + std::to_string(reader.line()) +
             " that the reference rejects or does not have");
      const Row& want = expected[got];
      if (reader.line() != want.line)
        fail("row " + std::to_string(got) + " comes from line " + std::to_string(reader.line()) +
             ", the reference says line " + std::to_string(want.line));
      for (int k = 0; k < dims; ++k) {
        double w = want.values[static_cast<std::size_t>(k)];
        if (std::memcmp(&w, &row[k], sizeof w) != 0)
          fail("line " + std::to_string(want.line) + " number " + std::to_string(k + 1) +
               ": read " + show(row[k]) + ", strtod gives " + show(w));
      }
      ++got;
    }
  } catch (const convexloc::ParseError& e) {
    if (badLine == 0)
      fail(std::string("ParseError on a file the reference accepts: ") + e.what() + " (line " +
           std::to_string(e.line()) + ")");
    if (e.line() != badLine)
      fail("ParseError names line " + std::to_string(e.line()) + ", the first bad line is " +
           std::to_string(badLine) + ": " + e.what());
    if (got != expected.size()) fail("rows before the bad line were lost");
    if (std::string_view(e.what()).empty()) fail("ParseError without a message");
    return 0;
  }
  if (badLine != 0)
    fail("RowReader accepted the file; the reference rejects line " + std::to_string(badLine));
  if (got != expected.size()) fail("RowReader stopped early");
  return 0;
}
