// convexloc — numbers and sizes as text, the same in every front end (the CLI, the Python
// module, the viewer).
#pragma once

#include <cstddef>
#include <string>

#include "convexloc/geometry.hpp"

namespace convexloc {

// the shortest decimal that reads back as exactly `v` ("0.1", "-2.5e-308", "inf")
std::string exactText(double v);
// "(x, y)" and "(x, y, z)", each coordinate with exactText
std::string exactText(Vec2 p);
std::string exactText(Vec3 p);

// a size in binary units, to 3 significant digits past 1 KiB: "512 B", "12.3 KiB",
// "4.07 MiB", "1.5 GiB"; beyond 1024 EiB (a count in a double) still in EiB, "3.1e+06 EiB"
std::string binarySize(double bytes);

}  // namespace convexloc
