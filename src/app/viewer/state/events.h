// events.h - the viewer's event lines: one "idview: ..." line on stdout per title change,
// selection, opened model, screenshot or shader reload, printed only with --print-events
// (scripts and tests follow the viewer through them; a person in a terminal sees nothing).
// Problems go to stderr whatever the flag says.
#pragma once

#include <cstdio>
#include <string>

namespace app {

class Events {
  public:
    explicit Events(bool print) : print_(print) {}

    void say(const std::string& line) const {
        if (!print_) return;
        std::printf("idview: %s\n", line.c_str());
        std::fflush(stdout);
    }
    static void problem(const std::string& line) {
        std::fprintf(stderr, "idview: %s\n", line.c_str());
    }

  private:
    bool print_;
};

} // namespace app
