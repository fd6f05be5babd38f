// exit_code.h - the exit code a run ends with when the validation layer spoke.
#pragma once

#include <cstdint>

namespace app {

// 0, or 3 with a line on stderr when validation reported anything (the CLI's exit codes).
int exitCode(uint32_t validationMessages);

} // namespace app
