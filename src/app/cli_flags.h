// cli_flags.h - the command line's flag table (cli_flags*.cpp): per flag its name, the value
// it takes, its help line and what it writes into Options, in groups by concern (the help
// prints one heading per group). cli.cpp parses with it.
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

struct FlagGroup {
    const char* title; // the help's heading
    std::vector<Flag> flags;
};

// Every flag, group by group, in the order --help lists them.
const std::vector<FlagGroup>& flagGroups();
// The same flags in one list.
const std::vector<Flag>& flags();

} // namespace app
