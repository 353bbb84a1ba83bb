// convexloc — a strict, fast reader for point text files.
#include "convexloc/text_reader.hpp"

#include <cerrno>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <string>

#include <sys/stat.h>

#include "convexloc/detail/chars.hpp"
#include "convexloc/error.hpp"
#include "io/text_scan.hpp"

namespace convexloc {
namespace {

using detail::isBlank;

// a short, printable quote of the text at the start of s, for messages
std::string quote(std::string_view s) {
  std::string out = "'";
  std::size_t n = 0;
  for (char c : s) {
    if (isBlank(c) || c == ',' || c == '#') break;
    if (++n > 24) {
      out += "...";
      break;
    }
    unsigned char u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    }
  }
  return out + "'";
}

// parses one number at s[pos..]; advances pos
double parseNumber(std::string_view s, std::size_t& pos, std::size_t lineNo) {
  std::size_t start = pos;
  const char* p = s.data() + pos;
  const char* end = s.data() + s.size();
  bool plus = p != end && *p == '+';
  if (plus) ++p;
  const char* digits = (p != end && *p == '-' && !plus) ? p + 1 : p;
  if (digits == end || !((*digits >= '0' && *digits <= '9') || *digits == '.'))
    throw ParseError("not a number: " + quote(s.substr(start)), lineNo);
  double v = 0.0;
  auto [ptr, ec] = detail::doubleFromChars(p, end, v);
  if (ec == std::errc::invalid_argument)
    throw ParseError("not a number: " + quote(s.substr(start)), lineNo);
  if (ptr != end && !isBlank(*ptr) && *ptr != ',' && *ptr != '#')
    throw ParseError("not a number: " + quote(s.substr(start)), lineNo);
  if (ec == std::errc::result_out_of_range) {
    // underflow rounds to zero, as strtod does; overflow has no finite nearest value
    std::string token(p, ptr);
    errno = 0;
    double r = std::strtod(token.c_str(), nullptr);
    if (r != 0.0)
      throw ParseError("number out of the range of double: " + quote(s.substr(start)), lineNo);
    v = token[0] == '-' ? -0.0 : 0.0;
  }
  pos = static_cast<std::size_t>(ptr - s.data());
  return v;
}

// the first position at or after `pos` that holds no blank
std::size_t skipBlanks(std::string_view line, std::size_t pos) {
  while (pos < line.size() && isBlank(line[pos])) ++pos;
  return pos;
}

// true when nothing but a comment is left from `pos`
bool atEnd(std::string_view line, std::size_t pos) {
  return pos == line.size() || line[pos] == '#';
}

// the complaint about the text at `pos`, after the last of `dims` numbers: one number too
// many, or other text
[[noreturn]] void rejectExtra(std::string_view line, std::size_t pos, std::size_t lineNo,
                              int dims) {
  std::size_t extra = pos;
  if (line[extra] == ',') ++extra;
  extra = skipBlanks(line, extra);
  std::size_t probe = extra;
  bool number = true;
  try {
    parseNumber(line, probe, lineNo);
  } catch (const ParseError&) {
    number = false;
  }
  if (number) throw ParseError("expected " + std::to_string(dims) + " numbers, found more", lineNo);
  throw ParseError(
      "unexpected text after " + std::to_string(dims) + " numbers: " + quote(line.substr(extra)),
      lineNo);
}

// parseRow on a line whose line ending is already gone
bool parseFields(std::string_view line, std::size_t lineNo, int dims, double* out) {
  std::size_t pos = skipBlanks(line, 0);
  if (atEnd(line, pos)) return false;
  for (int k = 0; k < dims; ++k) {
    if (k > 0) {
      // the separator: blanks, one optional comma, blanks; at least one of them
      const std::size_t before = pos;
      pos = skipBlanks(line, pos);
      if (pos < line.size() && line[pos] == ',') pos = skipBlanks(line, pos + 1);
      if (atEnd(line, pos))
        throw ParseError(
            "expected " + std::to_string(dims) + " numbers, found " + std::to_string(k), lineNo);
      if (pos == before)
        throw ParseError("numbers must be separated by whitespace or a comma", lineNo);
    }
    out[k] = parseNumber(line, pos, lineNo);
  }
  pos = skipBlanks(line, pos);
  if (!atEnd(line, pos)) rejectExtra(line, pos, lineNo, dims);
  return true;
}

}  // namespace

bool parseRow(std::string_view line, std::size_t lineNo, int dims, double* out) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return parseFields(line, lineNo, dims, out);
}

LineReader::LineReader(std::FILE* file) : file_(file), buf_(1 << 16) {}

LineReader::LineReader(std::string_view text) : text_(text) {}

bool LineReader::next(std::string_view& line) {
  if (!file_) {
    if (pos_ >= text_.size()) return false;
    std::size_t nl = text_.find('\n', pos_);
    std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
    line = text_.substr(pos_, end - pos_);
    pos_ = nl == std::string_view::npos ? text_.size() : nl + 1;
    return finish(line);
  }
  for (;;) {
    const char* base = buf_.data();
    const void* nl = std::memchr(base + begin_, '\n', end_ - begin_);
    if (nl) {
      std::size_t len = static_cast<std::size_t>(static_cast<const char*>(nl) - (base + begin_));
      line = {base + begin_, len};
      begin_ += len + 1;
      return finish(line);
    }
    if (fill()) continue;
    if (begin_ == end_) return false;
    // the last line has no newline; fill() may have grown (moved) the buffer: not `base`
    line = {buf_.data() + begin_, end_ - begin_};
    begin_ = end_;
    return finish(line);
  }
}

// counts the line, drops a CR before the LF, and applies the length limit to the text
bool LineReader::finish(std::string_view& line) {
  ++line_;
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() > kMaxLineBytes)
    throw ParseError("line longer than " + std::to_string(kMaxLineBytes) + " bytes", line_);
  return true;
}

// moves the unread bytes to the front and reads more; grows the buffer for a long line
bool LineReader::fill() {
  if (eof_) return false;
  if (begin_ > 0) {
    std::memmove(buf_.data(), buf_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (end_ == buf_.size()) {
    // room for the longest line, its CR and its LF
    if (buf_.size() >= kMaxLineBytes + 2)
      throw ParseError("line longer than " + std::to_string(kMaxLineBytes) + " bytes", line_ + 1);
    buf_.resize(std::min(buf_.size() * 2, kMaxLineBytes + 2));
  }
  std::size_t got = std::fread(buf_.data() + end_, 1, buf_.size() - end_, file_);
  end_ += got;
  if (got == 0) {
    if (std::ferror(file_))
      throw Error(std::string("read error: ") + std::strerror(errno), line_ + 1);
    eof_ = true;
    return false;
  }
  return true;
}

RowReader::RowReader(std::FILE* file, int dims) : lines_(file), dims_(dims) {}

bool RowReader::next(double* out) {
  std::string_view line;
  // the LineReader already dropped the line's one CR; another one is text
  while (lines_.next(line))
    if (parseFields(line, lines_.line(), dims_, out)) return true;
  return false;
}

InputFile::InputFile(const std::string& path) {
  if (path == "-") {
    file_ = stdin;
    return;
  }
  struct stat info {};
  if (::stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
    throw Error("cannot open: it is a directory, not a file");
  file_ = std::fopen(path.c_str(), "rb");
  if (!file_) throw Error(std::string("cannot open: ") + std::strerror(errno));
  owned_ = true;
}

InputFile::~InputFile() {
  if (owned_) std::fclose(file_);
}

namespace {

// every row of the point file at `path`, `Dims` numbers each, as points
template <class Point, int Dims>
PointListOf<Point> readPoints(const std::string& path) {
  InputFile in(path);
  RowReader reader(in.get(), Dims);
  PointListOf<Point> out;
  double row[Dims];
  while (reader.next(row)) {
    if constexpr (Dims == 2)
      out.points.push_back({row[0], row[1]});
    else
      out.points.push_back({row[0], row[1], row[2]});
    out.lines.push_back(reader.line());
  }
  out.lastLine = reader.line();
  return out;
}

}  // namespace

PointList readPoints2D(const std::string& path) {
  return readPoints<Vec2, 2>(path);
}

PointList3D readPoints3D(const std::string& path) {
  return readPoints<Vec3, 3>(path);
}

}  // namespace convexloc
