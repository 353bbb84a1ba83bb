// convexloc-viewer — text laid out in lines.
#include "logic/base/text_layout.hpp"

#include <algorithm>

namespace convexloc::viewer {

std::vector<std::string> breakAtSpaces(std::string_view text, double width,
                                       const MeasureText& measure, std::string_view indent) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t nl = std::min(text.find('\n', start), text.size());
    const std::string_view para = text.substr(start, nl - start);
    std::string line;
    std::size_t at = 0;
    while (at < para.size()) {
      std::size_t end = para.find(' ', at);
      if (end == std::string_view::npos) end = para.size();
      const std::string_view word = para.substr(at, end - at);
      const std::string joined = line.empty() ? std::string(word) : line + " " + std::string(word);
      if (!line.empty() && measure(joined).x > width) {
        lines.push_back(line);
        line = std::string(indent) + std::string(word);
      } else {
        line = joined;
      }
      at = end + 1;
    }
    lines.push_back(line);
    start = nl + 1;
  }
  return lines;
}

}  // namespace convexloc::viewer
