// convexloc-viewer — the font's characters.
#include "logic/base/glyphs.hpp"

#include <array>

namespace convexloc::viewer {
namespace {

constexpr std::array<GlyphRange, 7> kRanges{{{0x0020, 0x00FF},
                                             {0x0370, 0x03FF},
                                             {0x2000, 0x209F},
                                             {0x2190, 0x21FF},
                                             {0x2200, 0x22FF},
                                             {0x2300, 0x23FF},
                                             {0x25A0, 0x25FF}}};

constexpr char32_t kReplacement = 0xFFFD;

// the code point at text[i] and its length in bytes (kReplacement and 1 when malformed)
char32_t decode(std::string_view text, std::size_t i, std::size_t& length) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = byte(i);
  length = 1;
  if (b < 0x80) return b;
  const std::size_t n = b >= 0xF0 ? 4 : b >= 0xE0 ? 3 : b >= 0xC0 ? 2 : 0;
  if (n == 0 || i + n > text.size()) return kReplacement;
  char32_t c = b & (0x7F >> n);
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return kReplacement;
    c = (c << 6) | (byte(i + k) & 0x3F);
  }
  length = n;
  return c;
}

}  // namespace

std::span<const GlyphRange> fontGlyphRanges() {
  return kRanges;
}

std::optional<char32_t> firstMissingGlyph(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    std::size_t length = 1;
    const char32_t c = decode(text, i, length);
    i += length;
    if (c == '\n' || c == '\t' || c == '\r') continue;
    bool found = false;
    for (const GlyphRange& r : kRanges) found = found || (r.first <= c && c <= r.last);
    if (!found) return c;
  }
  return std::nullopt;
}

}  // namespace convexloc::viewer
