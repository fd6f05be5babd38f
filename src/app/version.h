// version.h - what `idview --version` prints: the project version and the commit the program
// was built from (cmake/version.cmake writes it at every build).
#pragma once

#include <string>

namespace app {

// "idview 0.1.0 (COMMIT)": COMMIT is git describe's answer at build time, "unknown" outside git.
std::string versionLine();

} // namespace app
