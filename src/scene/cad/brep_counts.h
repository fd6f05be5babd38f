// brep_counts.h - a BREP file's section counts weighed against its size, before Open CASCADE
// reads it. Its reader believes the count each section announces ("Curves 14") and, past the
// end of a file that holds fewer entries, goes on reading nothing for as many: a count of
// 4e8 in a 48 kB file kept it busy for minutes at full CPU. No entry of any section takes
// under two bytes (a digit and a line end), so a count above half the bytes after it cannot
// be the file's. Every shape of the last section ends its list of sub-shapes with a '*', so
// fewer of those than shapes announced means a cut-off file, on which the reader loops.
#pragma once

#include <cstdint>
#include <istream>
#include <optional>
#include <string>

namespace scene {

// Why the BREP text in `in` (`fileBytes` long) cannot hold what it announces, or nothing.
std::optional<std::string> implausibleBrepCount(std::istream& in, uint64_t fileBytes);

} // namespace scene
