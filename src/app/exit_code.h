// exit_code.h - idview's exit codes, listed once (the usage and the manual page print this
// table), and the code a run ends with when the validation layer spoke.
#pragma once

#include <cstdint>
#include <vector>

namespace app {

struct ExitCode {
    int code;
    const char* meaning;
};
// Every code idview exits with, in order.
const std::vector<ExitCode>& exitCodes();

// 0, or 3 with a line on stderr when validation reported anything (the CLI's exit codes).
int exitCode(uint32_t validationMessages);

} // namespace app
