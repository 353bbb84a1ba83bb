// convexloc-viewer — text for XML documents (the scene's SVG, the Why O(1) plots).
#pragma once

#include <string>
#include <string_view>

namespace convexloc::viewer {

// `text` with &, <, >, " and ' written as entities and the control characters XML 1.0
// forbids (all below 0x20 but tab and newline) left out
std::string xmlEscape(std::string_view text);

}  // namespace convexloc::viewer
