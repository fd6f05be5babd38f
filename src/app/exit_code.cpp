// exit_code.cpp - validation messages to the CLI's exit code.
#include "app/exit_code.h"

#include <cstdio>

namespace app {

int exitCode(uint32_t validationMessages) {
    if (validationMessages == 0) return 0;
    std::fprintf(stderr, "idview: the validation layer reported %u messages (see above)\n",
                 validationMessages);
    return 3;
}

} // namespace app
