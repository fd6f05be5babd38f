// exit_code.cpp - the exit codes' table, and validation messages to the CLI's exit code.
#include "app/exit_code.h"

#include <cstdio>

namespace app {

namespace {
constexpr int kValidationReported = 3;
}

const std::vector<ExitCode>& exitCodes() {
    static const std::vector<ExitCode> codes = {
        {0, "ok"},
        {1, "error (no device, missing features, I/O)"},
        {2, "bad command line"},
        {kValidationReported, "validation messages were reported (with --validation)"},
    };
    return codes;
}

int exitCode(uint32_t validationMessages) {
    if (validationMessages == 0) return 0;
    std::fprintf(stderr, "idview: the validation layer reported %u messages (see above)\n",
                 validationMessages);
    return kValidationReported;
}

} // namespace app
