// convexloc — reading points from text: one point per line (2 numbers for a polygon's
// vertex or a 2D point, 3 for a 3D point), numbers separated by whitespace and/or one comma,
// '#' starting a comment, blank lines skipped, LF or CRLF.
// A number is a decimal as C's strtod reads it (sign, digits, point, exponent; no hex,
// inf or nan) and becomes the nearest double.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/geometry.hpp"

namespace convexloc {

// The longest line accepted, in bytes; a longer one is a ParseError, never an allocation.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

// Parses one line into `dims` numbers. Returns false for a blank or comment line.
// Throws ParseError carrying `lineNo` with the problem: a bad number, too few or too many.
bool parseRow(std::string_view line, std::size_t lineNo, int dims, double* out);

// The lines of a file, read through a buffer in constant memory, or of text in memory;
// numbered from 1 and handed out without their line ending (LF, or CRLF).
class LineReader {
 public:
  // reads from `file`, which stays owned by the caller
  explicit LineReader(std::FILE* file);
  // reads `text`, which must outlive the reader
  explicit LineReader(std::string_view text);
  // the next line, valid until the following call; false at the end of the input.
  // Throws ParseError for a line longer than kMaxLineBytes, Error on a read failure.
  bool next(std::string_view& line);
  // the number of the line last returned (1-based)
  std::size_t line() const noexcept { return line_; }

 private:
  bool finish(std::string_view& line);
  bool fill();
  std::FILE* file_ = nullptr;        // the file read, or null for text in memory
  std::string_view text_;            // the text in memory
  std::size_t pos_ = 0;              // where the next line of text_ starts
  std::vector<char> buf_;            // the file's bytes read and not yet handed out
  std::size_t begin_ = 0, end_ = 0;  // the unread bytes are buf_[begin_, end_)
  std::size_t line_ = 0;             // lines handed out so far
  bool eof_ = false;                 // the file has no more bytes
};

// Streams the data rows of a file in constant memory.
class RowReader {
 public:
  // reads from `file`, which stays owned by the caller; `dims` numbers per row
  RowReader(std::FILE* file, int dims);
  // the next data row into out[0..dims); false at the end of the input.
  // Throws ParseError (with the line) on bad text, Error on a read failure.
  bool next(double* out);
  // the line number of the row last returned (1-based)
  std::size_t line() const noexcept { return lines_.line(); }

 private:
  LineReader lines_;
  int dims_;
};

// An opened file, closed when it goes; "-" is standard input. Throws Error when it
// cannot be opened.
class InputFile {
 public:
  explicit InputFile(const std::string& path);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  std::FILE* get() const noexcept { return file_; }

 private:
  std::FILE* file_ = nullptr;  // stdin for "-"
  bool owned_ = false;         // closed by the destructor
};

// Every point of a point file, with the line each came from.
template <class Point>
struct PointListOf {
  std::vector<Point> points;
  std::vector<std::size_t> lines;
  std::size_t lastLine = 0;  // the number of lines read
};
using PointList = PointListOf<Vec2>;
using PointList3D = PointListOf<Vec3>;

// Every 2D point (2 numbers a line) of the file at `path` ("-" is standard input).
PointList readPoints2D(const std::string& path);
// Every 3D point (3 numbers a line) of the file at `path` ("-" is standard input).
PointList3D readPoints3D(const std::string& path);

}  // namespace convexloc
