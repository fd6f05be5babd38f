// version.cpp - the version line; the only file that includes the generated commit header, so
// a new commit recompiles this one file.
#include "app/version.h"

#include "idview_commit.h"

namespace app {

std::string versionLine() {
    return std::string("idview ") + IDVIEW_VERSION + " (" + IDVIEW_COMMIT + ")";
}

} // namespace app
