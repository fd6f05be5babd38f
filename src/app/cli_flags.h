// cli_flags.h - the command line's flag table (cli_flags.cpp): per flag its name, the value
// it takes, its help line and what it writes into Options. cli.cpp parses with it.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/cli.h"

namespace app {

struct Flag {
    const char* name;
    const char* value; // nullptr for a switch
    std::string help;
    std::function<void(Options&, const std::string&)> apply;
};

const std::vector<Flag>& flags();

// "a,b,,c" -> {"a", "b", "", "c"}: every item, empty ones included (they are refused later).
std::vector<std::string> commaList(const std::string& text);

} // namespace app
