// cli_flags.h - the command line's flag table (cli_flags.cpp): per flag its name, the value
// it takes, its help line and what it writes into Options. cli.cpp parses with it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/cli.h"
#include "app/cli_values.h"

namespace app {

struct Flag {
    const char* name;
    const char* value; // nullptr for a switch
    std::string help;
    std::function<void(Options&, const std::string&)> apply;
    // Read only by headless runs: the viewer says it ignores them (ignoredByViewer).
    bool headlessOnly = false;
};

const std::vector<Flag>& flags();

} // namespace app
