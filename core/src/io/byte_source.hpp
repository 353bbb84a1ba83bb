// convexloc (internal) — the bytes of a binary-or-text mesh file (STL, PLY), read through a
// buffer from a FILE or straight from memory, with the offset of every byte and the number
// of every line, so that an error can name either.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace convexloc::detail {

// Throws ParseError "byte N: problem" (line 0): where a binary file goes wrong.
[[noreturn]] void failAtByte(std::uint64_t offset, const std::string& problem);

// A forward-only reader of bytes and lines. Memory in use stays within the buffer (64 KiB,
// grown only for a line, up to kMaxLineBytes) whatever the file's size.
class ByteSource {
 public:
  // reads from `file`, which stays owned by the caller, from where it stands
  explicit ByteSource(std::FILE* file);
  // reads `bytes`, which must outlive the reader
  explicit ByteSource(std::string_view bytes);

  // the bytes consumed so far (the offset of the next one)
  std::uint64_t offset() const noexcept { return consumed_ + begin_; }
  // the size of the whole input, when known (memory, or a file that can seek)
  std::optional<std::uint64_t> size() const noexcept { return size_; }
  // the number of the line nextLine returned last (1-based)
  std::size_t line() const noexcept { return line_; }

  // Up to `n` (at most kChunk) bytes ahead, not consumed; shorter only at the end.
  std::string_view peek(std::size_t n);
  // Consumes and returns the next `n` (at most kChunk) bytes, valid until the next call;
  // shorter only at the end of the input.
  std::string_view take(std::size_t n);
  // Skips `n` bytes; returns how many there were (fewer at the end of the input).
  std::uint64_t skip(std::uint64_t n);
  // whether every byte has been consumed
  bool atEnd() { return peek(1).empty(); }
  // The next line without its LF (or CRLF), counted; false at the end of the input.
  // ParseError for a line over kMaxLineBytes.
  bool nextLine(std::string_view& line);

  // the most bytes take() and peek() hand out at once
  static constexpr std::size_t kChunk = std::size_t{1} << 16;

 private:
  std::size_t ensure(std::size_t n);
  void fill(std::size_t need);
  std::FILE* file_ = nullptr;        // null for bytes in memory
  const char* data_ = nullptr;       // the bytes at hand: the memory, or buf_
  std::size_t begin_ = 0, end_ = 0;  // unread bytes are data_[begin_, end_)
  std::uint64_t consumed_ = 0;       // bytes dropped from the front of buf_ so far
  std::vector<char> buf_;
  std::optional<std::uint64_t> size_;
  std::size_t line_ = 0;
  bool eof_ = false;  // no more bytes will come
};

// the value of 4 or 8 bytes stored little-endian (`big`: big-endian) as T
template <class T>
T loadScalar(const char* p, bool big) noexcept {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (big)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  // the bytes are now little-endian; assemble the value whatever the host's order
  std::uint64_t bits = 0;
  for (std::size_t i = sizeof(T); i-- > 0;) bits = bits << 8 | b[i];
  if constexpr (sizeof(T) == 1) {
    return static_cast<T>(static_cast<std::uint8_t>(bits));
  } else if constexpr (sizeof(T) == 2) {
    return static_cast<T>(static_cast<std::uint16_t>(bits));
  } else if constexpr (sizeof(T) == 4) {
    const auto u = static_cast<std::uint32_t>(bits);
    T out;
    std::memcpy(&out, &u, 4);
    return out;
  } else {
    T out;
    std::memcpy(&out, &bits, 8);
    return out;
  }
}

// appends `v` as its 1, 2, 4 or 8 bytes, little-endian (`big`: big-endian)
template <class T>
void storeScalar(std::string& out, T v, bool big) {
  std::uint64_t bits = 0;
  if constexpr (sizeof(T) == 4 || sizeof(T) == 8) {
    std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t> u;
    std::memcpy(&u, &v, sizeof(T));
    bits = u;
  } else {
    bits = static_cast<std::uint64_t>(v);
  }
  char b[sizeof(T)];
  for (std::size_t i = 0; i < sizeof(T); ++i)
    b[big ? sizeof(T) - 1 - i : i] = static_cast<char>((bits >> (8 * i)) & 0xff);
  out.append(b, sizeof(T));
}

}  // namespace convexloc::detail
