// docs_main.cpp - idview-docs: prints idview's manual page (man) or bash completion (bash),
// written from the flag table the program parses with (tools/flag_docs.h).
#include <cstdio>
#include <string>

#include "tools/flag_docs.h"

int main(int argc, char** argv) {
    const std::string what = argc == 2 ? argv[1] : "";
    std::string text;
    if (what == "man")
        text = docs::manualPage();
    else if (what == "bash")
        text = docs::bashCompletion();
    else {
        std::fprintf(stderr, "usage: idview-docs man|bash\n");
        return 2;
    }
    std::fputs(text.c_str(), stdout);
    return 0;
}
