// convexloc — the buffered byte and line reader of the binary-or-text mesh formats.
#include "io/byte_source.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "convexloc/error.hpp"
#include "convexloc/text_reader.hpp"

namespace convexloc::detail {

void failAtByte(std::uint64_t offset, const std::string& problem) {
  throw ParseError("byte " + std::to_string(offset) + ": " + problem);
}

namespace {

// the bytes from where `file` stands to its end, when it can seek (a regular file, a
// memory stream), and it is left where it stood
std::optional<std::uint64_t> remainingSize(std::FILE* file) {
  const long here = std::ftell(file);
  if (here < 0 || std::fseek(file, 0, SEEK_END) != 0) return std::nullopt;
  const long end = std::ftell(file);
  if (std::fseek(file, here, SEEK_SET) != 0)
    throw Error(std::string("cannot seek back in the file: ") + std::strerror(errno));
  if (end < here) return std::nullopt;
  return static_cast<std::uint64_t>(end - here);
}

}  // namespace

ByteSource::ByteSource(std::FILE* file) : file_(file), buf_(kChunk), size_(remainingSize(file)) {
  data_ = buf_.data();
}

ByteSource::ByteSource(std::string_view bytes)
    : data_(bytes.data()), end_(bytes.size()), size_(bytes.size()), eof_(true) {}

// moves the unread bytes to the front of buf_ and reads until `need` are unread or the
// file ends; grows buf_ to hold `need`
void ByteSource::fill(std::size_t need) {
  const std::size_t unread = end_ - begin_;
  std::memmove(buf_.data(), buf_.data() + begin_, unread);
  consumed_ += begin_;
  begin_ = 0;
  end_ = unread;
  if (buf_.size() < need) buf_.resize(need);
  data_ = buf_.data();
  while (end_ < need && !eof_) {
    const std::size_t got = std::fread(buf_.data() + end_, 1, buf_.size() - end_, file_);
    if (got == 0) {
      if (std::ferror(file_)) throw Error(std::string("read error: ") + std::strerror(errno));
      eof_ = true;
    }
    end_ += got;
  }
}

// makes `n` bytes available when the input holds them; returns how many are
std::size_t ByteSource::ensure(std::size_t n) {
  if (end_ - begin_ < n && !eof_) fill(n);
  return std::min(n, end_ - begin_);
}

std::string_view ByteSource::peek(std::size_t n) {
  // ensure() may move the unread bytes: only then do data_ and begin_ say where they are
  const std::size_t available = ensure(std::min(n, kChunk));
  return {data_ + begin_, available};
}

std::string_view ByteSource::take(std::size_t n) {
  const std::string_view out = peek(n);
  begin_ += out.size();
  return out;
}

std::uint64_t ByteSource::skip(std::uint64_t n) {
  std::uint64_t done = 0;
  while (done < n) {
    const std::size_t step = static_cast<std::size_t>(std::min<std::uint64_t>(n - done, kChunk));
    const std::size_t got = take(step).size();
    done += got;
    if (got < step) break;
  }
  return done;
}

bool ByteSource::nextLine(std::string_view& line) {
  std::size_t scanned = 0;  // bytes already searched for the LF
  for (;;) {
    const char* from = data_ + begin_ + scanned;
    const std::size_t left = end_ - begin_ - scanned;  // nothing to search (perhaps no buffer)
    const char* lf = left ? static_cast<const char*>(std::memchr(from, '\n', left)) : nullptr;
    if (lf || eof_) {
      const std::size_t len = lf ? static_cast<std::size_t>(lf - (data_ + begin_)) : end_ - begin_;
      if (!lf && len == 0) return false;
      line = {data_ + begin_, len};
      begin_ += len + (lf ? 1 : 0);
      ++line_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.size() > kMaxLineBytes)
        throw ParseError("line longer than " + std::to_string(kMaxLineBytes) + " bytes", line_);
      return true;
    }
    scanned = end_ - begin_;
    if (scanned > kMaxLineBytes + 1)
      throw ParseError("line longer than " + std::to_string(kMaxLineBytes) + " bytes", line_ + 1);
    fill(std::max(buf_.size(), scanned + kChunk));
  }
}

}  // namespace convexloc::detail
