// The point text format: parseRow on single lines, RowReader on whole streams (through
// fmemopen), readPoints2D on a temporary file.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"

using namespace convexloc;
using testing::AllOf;
using testing::HasSubstr;

namespace {

// the two numbers of a data line (fails the test when the line is not one)
std::pair<double, double> row(std::string_view line) {
  double out[2] = {-7, -7};
  EXPECT_TRUE(parseRow(line, 1, 2, out)) << "'" << line << "' was skipped";
  return {out[0], out[1]};
}

// the line is blank or a comment
bool skipped(std::string_view line) {
  double out[2] = {-7, -7};
  return !parseRow(line, 1, 2, out);
}

// the ParseError for a line given line number `lineNo`
ParseError parseError(std::string_view line, std::size_t lineNo = 5) {
  double out[2];
  try {
    parseRow(line, lineNo, 2, out);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "'" << line << "' was accepted";
  return ParseError("");
}

// every row of `text` through RowReader, with the line each came from
struct Rows {
  std::vector<std::pair<double, double>> values;
  std::vector<std::size_t> lines;
};
Rows readAll(const std::string& text, int dims = 2) {
  std::FILE* f = fmemopen(const_cast<char*>(text.data()), text.size(), "r");
  EXPECT_NE(f, nullptr);
  Rows rows;
  if (!f) return rows;
  try {
    RowReader reader(f, dims);
    double out[3];
    while (reader.next(out)) {
      rows.values.push_back({out[0], dims > 1 ? out[1] : 0.0});
      rows.lines.push_back(reader.line());
    }
  } catch (...) {
    std::fclose(f);
    throw;
  }
  std::fclose(f);
  return rows;
}

// the ParseError RowReader raises on `text`
ParseError readError(const std::string& text) {
  try {
    readAll(text);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "the text was accepted";
  return ParseError("");
}

// === parseRow: separators, comments, line ends

TEST(ParseRow, Separators) {
  using P = std::pair<double, double>;
  EXPECT_EQ(row("1 2"), P(1, 2));
  EXPECT_EQ(row("1\t2"), P(1, 2));
  EXPECT_EQ(row("1,2"), P(1, 2));
  EXPECT_EQ(row("1 , 2"), P(1, 2));
  EXPECT_EQ(row("1,\t2"), P(1, 2));
  EXPECT_EQ(row("   1    2   "), P(1, 2));
  EXPECT_EQ(row("\t-1.5\t\t2.25\t"), P(-1.5, 2.25));
  EXPECT_EQ(row(".5 5."), P(0.5, 5));
  EXPECT_EQ(row("1e3 -2E-2"), P(1000, -0.02));
}

TEST(ParseRow, CommentsBlanksAndLineEnds) {
  using P = std::pair<double, double>;
  EXPECT_TRUE(skipped(""));
  EXPECT_TRUE(skipped("   \t "));
  EXPECT_TRUE(skipped("# a comment 1 2"));
  EXPECT_TRUE(skipped("   # indented comment"));
  EXPECT_TRUE(skipped("\r"));
  EXPECT_EQ(row("1 2 # inline"), P(1, 2));
  EXPECT_EQ(row("1 2#tight"), P(1, 2));
  EXPECT_EQ(row("1 2\r"), P(1, 2));
  EXPECT_EQ(row("3,4 \r"), P(3, 4));
}

// === parseRow: numbers

TEST(ParseRow, SignsZerosAndExtremes) {
  EXPECT_EQ(row("+1 +2.5").first, 1.0);
  EXPECT_EQ(row("+1 +2.5").second, 2.5);
  const auto [nz, pz] = row("-0.0 0");
  EXPECT_EQ(nz, 0.0);
  EXPECT_TRUE(std::signbit(nz));
  EXPECT_FALSE(std::signbit(pz));
  EXPECT_EQ(row("5e-324 1").first, std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(row("1.7976931348623157e308 0").first, std::numeric_limits<double>::max());
  // underflow rounds to zero, keeping the sign
  const auto [u, nu] = row("1e-400 -1e-400");
  EXPECT_EQ(u, 0.0);
  EXPECT_FALSE(std::signbit(u));
  EXPECT_EQ(nu, 0.0);
  EXPECT_TRUE(std::signbit(nu));
  // the nearest double
  EXPECT_EQ(row("0.1 0.3").first, 0.1);
  EXPECT_EQ(row("0.1 0.3").second, 0.3);
  EXPECT_EQ(row("9007199254740993 0").first, 9007199254740992.0);
}

TEST(ParseRow, OverflowIsAnErrorMentioningTheRange) {
  const ParseError e = parseError("1e400 0", 12);
  EXPECT_THAT(e.what(), AllOf(HasSubstr("range"), HasSubstr("1e400")));
  EXPECT_EQ(e.line(), 12u);
  EXPECT_THAT(parseError("0 -1e309").what(), HasSubstr("range"));
}

TEST(ParseRow, RejectsWhatStrtodWouldNotReadAsADecimal) {
  for (const char* bad : {"inf 0", "0 -inf", "nan 1", "1 NaN", "0x1p3 0", "1.2.3 0", "1e 0",
                          "- 1 2", "+-1 2", "abc 1", ". 1", "1 2x", "1,,2", "1;2"}) {
    const ParseError e = parseError(bad, 9);
    EXPECT_EQ(e.line(), 9u) << bad;
    EXPECT_NE(std::string(e.what()), "") << bad;
  }
  EXPECT_THAT(parseError("inf 0").what(), AllOf(HasSubstr("not a number"), HasSubstr("'inf'")));
  EXPECT_THAT(parseError("0x1p3 0").what(), HasSubstr("not a number"));
  EXPECT_THAT(parseError("1.2.3 4").what(), HasSubstr("1.2.3"));
}

TEST(ParseRow, FieldCounts) {
  EXPECT_THAT(parseError("1 2 3").what(), HasSubstr("found more"));
  EXPECT_THAT(parseError("1,2,3").what(), HasSubstr("found more"));
  EXPECT_THAT(parseError("1").what(), HasSubstr("expected 2 numbers, found 1"));
  EXPECT_THAT(parseError("1 # 2").what(), HasSubstr("found 1"));
  EXPECT_THAT(parseError("1,").what(), HasSubstr("found 1"));
  EXPECT_THAT(parseError("1 2 x").what(), HasSubstr("unexpected text"));
  // three numbers where three are wanted, one where one is
  double out[3];
  EXPECT_TRUE(parseRow("1 2 3", 1, 3, out));
  EXPECT_EQ(out[2], 3.0);
  EXPECT_TRUE(parseRow("-4", 1, 1, out));
  EXPECT_EQ(out[0], -4.0);
}

TEST(ParseRow, BinaryBytesAreQuotedPrintably) {
  const std::string bytes("\x01\x02\xff 1", 5);
  const ParseError e = parseError(bytes);
  EXPECT_THAT(e.what(), AllOf(HasSubstr("not a number"), HasSubstr("\\x01"), HasSubstr("\\xff")));
  const std::string nul("1 \0", 3);
  EXPECT_THAT(parseError(nul).what(), HasSubstr("\\x00"));
  // a long garbage token is cut short in the message
  const ParseError longer = parseError(std::string(500, 'z') + " 1");
  EXPECT_LT(std::string(longer.what()).size(), 100u);
}

// === RowReader: streams

TEST(RowReader, LinesAndNumbers) {
  const Rows r = readAll("# header\n\n1 2\n  \n3,4 # four\r\n5\t6\n# end\n7 8");
  ASSERT_EQ(r.values.size(), 4u);
  EXPECT_EQ(r.values[0], std::make_pair(1.0, 2.0));
  EXPECT_EQ(r.values[1], std::make_pair(3.0, 4.0));
  EXPECT_EQ(r.values[2], std::make_pair(5.0, 6.0));
  EXPECT_EQ(r.values[3], std::make_pair(7.0, 8.0));
  EXPECT_EQ(r.lines, (std::vector<std::size_t>{3, 5, 6, 8}));
}

TEST(RowReader, CrlfThroughout) {
  const Rows r = readAll("1 2\r\n\r\n# c\r\n3 4\r\n");
  ASSERT_EQ(r.values.size(), 2u);
  EXPECT_EQ(r.values[1], std::make_pair(3.0, 4.0));
  EXPECT_EQ(r.lines, (std::vector<std::size_t>{1, 4}));
}

TEST(RowReader, EmptyAndCommentOnlyInputs) {
  EXPECT_TRUE(readAll("").values.empty());
  EXPECT_TRUE(readAll("\n\n# nothing\n").values.empty());
  EXPECT_TRUE(readAll("# no newline at the end").values.empty());
}

TEST(RowReader, ErrorsCarryTheirLine) {
  const ParseError e = readError("1 2\n3 4\n\n# c\n5 x\n6 7\n");
  EXPECT_EQ(e.line(), 5u);
  EXPECT_THAT(e.what(), HasSubstr("'x'"));
  EXPECT_EQ(readError("1 2\n3\n").line(), 2u);
  EXPECT_EQ(readError("1 2\r\n\r\n1e999 0\r\n").line(), 3u);
  EXPECT_EQ(readError("1 2\n3 4 5").line(), 2u);  // the last line has no newline
}

TEST(RowReader, ManyRowsAcrossBufferRefills) {
  std::string text;
  const int count = 50000;
  for (int i = 0; i < count; ++i) text += std::to_string(i) + ", " + std::to_string(-i) + "\n";
  const Rows r = readAll(text);
  ASSERT_EQ(r.values.size(), static_cast<std::size_t>(count));
  for (int i = 0; i < count; i += 997) {
    EXPECT_EQ(r.values[i].first, i);
    EXPECT_EQ(r.values[i].second, -i);
    EXPECT_EQ(r.lines[i], static_cast<std::size_t>(i + 1));
  }
}

TEST(RowReader, LongestLineIsAcceptedLongerIsAnError) {
  // exactly kMaxLineBytes bytes (padding after the numbers): accepted
  std::string longest = "1 2";
  longest.resize(kMaxLineBytes, ' ');
  const Rows ok = readAll("0 0\n" + longest + "\n3 4\n");
  ASSERT_EQ(ok.values.size(), 3u);
  EXPECT_EQ(ok.values[1], std::make_pair(1.0, 2.0));
  EXPECT_EQ(ok.lines[2], 3u);
  // one byte more: a ParseError naming the line, with or without a newline after it
  const std::string tooLong = longest + " ";
  for (const std::string& text :
       {"0 0\n" + tooLong + "\n3 4\n", "0 0\n" + tooLong, "0 0\n" + tooLong + tooLong + "\n"}) {
    const ParseError e = readError(text);
    EXPECT_THAT(e.what(), HasSubstr("longer than"));
    EXPECT_EQ(e.line(), 2u);
  }
  // a far longer line of digits fails the same way, without reading it all in
  const ParseError huge = readError(std::string(3 * kMaxLineBytes, '7'));
  EXPECT_THAT(huge.what(), HasSubstr("longer than"));
  EXPECT_EQ(huge.line(), 1u);
}

TEST(RowReader, ThreeDimensionalRows) {
  const Rows r = readAll("1 2 3\n", 3);
  ASSERT_EQ(r.values.size(), 1u);
  EXPECT_THROW(readAll("1 2\n", 3), ParseError);
}

// === readPoints2D: a real file

TEST(ReadPoints2D, FileWithLines) {
  char path[] = "/tmp/convexloc_reader_XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  const std::string text = "# square\n0 0\n1,0\n\n1 1 # corner\n0 1";
  ASSERT_EQ(write(fd, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  close(fd);
  const PointList list = readPoints2D(path);
  std::remove(path);
  ASSERT_EQ(list.points.size(), 4u);
  EXPECT_EQ(list.points[2], (Vec2{1, 1}));
  EXPECT_EQ(list.lines, (std::vector<std::size_t>{2, 3, 5, 6}));
  EXPECT_EQ(list.lastLine, 6u);
}

TEST(ReadPoints2D, MissingFileIsAnError) {
  try {
    readPoints2D("/nonexistent/dir/points.txt");
    FAIL() << "opened a missing file";
  } catch (const ParseError&) {
    FAIL() << "a missing file is not a parse error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("cannot open"));
  }
}

}  // namespace

// found by fuzz_points_reader: only the one CR before the LF is a line ending; a second CR
// is text, as parseRow says for the same line (the corpus keeps the fuzzer's input)
TEST(RowReader, OnlyOneCarriageReturnEndsALine) {
  ParseError e = readError("0 3\r\r\n1 2\r\n");
  EXPECT_EQ(e.line(), 1u);
  double out[2];
  EXPECT_THROW(parseRow("0 3\r\r", 1, 2, out), ParseError);
  Rows rows = readAll("0 3\r\n1 2\r\n");
  ASSERT_EQ(rows.values.size(), 2u);
  EXPECT_EQ(rows.values[1], (std::pair<double, double>{1, 2}));
}
