// Sizes of the heavy tests under the sanitizers: CONVEXLOC_HOSTILE_SCALE (default 1)
// multiplies them; scripts/test.sh sets it to 0.1 for the ASan + UBSan run, and the plain run
// keeps the full sizes. The adversarial points of a shape are kept whatever its size.
#pragma once

#include <cstddef>
#include <cstdlib>

namespace testscale {

// the factor from CONVEXLOC_HOSTILE_SCALE: a positive number, else 1
inline double factor() {
  const char* env = std::getenv("CONVEXLOC_HOSTILE_SCALE");
  const double scale = env ? std::strtod(env, nullptr) : 1.0;
  return scale > 0 ? scale : 1.0;
}

// full times the factor, never below `floor`
inline std::size_t scaled(std::size_t full, std::size_t floor) {
  const auto n = static_cast<std::size_t>(static_cast<double>(full) * factor());
  return n < floor ? floor : n;
}

}  // namespace testscale
