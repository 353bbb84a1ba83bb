// convexloc-viewer — Why O(1)'s timings recorded to a text file and read back, so that a
// lecture's slide shows the same curves on any machine under any load (--why-record,
// --why-from). The format, one record a line, `#` comments and blank lines skipped:
//   convexloc-why 1
//   config TRACED TIMED MIN_SECONDS LINEAR_LIMIT LINEAR_LIMIT_3D SEED
//   2d METHOD N PREDICATES CELL_EDGES NS_PER_QUERY BYTES
//   3d METHOD F PREDICATES CELL_EDGES NS_PER_QUERY BYTES
//   memory GAP PAPER_SLABS PAPER_BYTES UNIFORM_BYTES POLAR_BYTES
// The sizes measured are the N (F) of the 2d (3d) lines. GL-free.
#pragma once

#include <string>

#include "logic/teach/scaling.hpp"

namespace convexloc::viewer {

// a measurement as the record file's text (doubles written to round-trip exactly)
std::string scalingRecord(const ScalingResult& r, const ScalingConfig& c);

// Reads a record's text; `source` names it in errors. False and `error` ("FILE:LINE:
// problem") on the first line that is not a record.
bool parseScalingRecord(const std::string& text, const std::string& source, ScalingResult& r,
                        ScalingConfig& c, std::string& error);

// reads the record file at `path`; false and `error` when it cannot be read or is not one
bool readScalingRecord(const std::string& path, ScalingResult& r, ScalingConfig& c,
                       std::string& error);

// reads the record file at `path` into `worker`, shown as if just measured; false and
// `error` when it cannot be read or is not one
bool showScalingRecord(const std::string& path, ScalingWorker& worker, std::string& error);

// writes scalingRecord to `path`; false and `error` when it cannot be written
bool writeScalingRecord(const std::string& path, const ScalingResult& r, const ScalingConfig& c,
                        std::string& error);

}  // namespace convexloc::viewer
