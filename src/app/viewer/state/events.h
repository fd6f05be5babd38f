// events.h - the viewer's event records: one JSON object a line on stdout (JSON Lines), such
// as {"event":"selected","parts":3}, per title change, selection, opened model, screenshot or
// shader reload, printed only with --print-events (scripts and tests follow the viewer through
// them, by field; a person in a terminal sees nothing). docs/viewer.md lists them. Problems go
// to stderr as lines for people, whatever the flag says.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

#include "util/json_writer.h"

namespace app {

class Events {
  public:
    // `out`: where records go (stdout; a unit test's own file).
    explicit Events(bool print, std::FILE* out = stdout) : print_(print), out_(out) {}

    // The record {"event":event, ...}: `fields(json)` writes its members. Without
    // --print-events it is not called, so a record costs nothing then.
    template <typename Fields>
    void say(std::string_view event, const Fields& fields) const {
        if (!print_) return;
        util::JsonWriter json;
        json.beginObject().member("event", event);
        fields(json);
        write(json.endObject().text());
    }
    // A record with no field but its name.
    void say(std::string_view event) const {
        say(event, [](util::JsonWriter&) {});
    }
    static void problem(const std::string& line) {
        std::fprintf(stderr, "idview: %s\n", line.c_str());
    }

  private:
    void write(const std::string& record) const {
        std::fprintf(out_, "%s\n", record.c_str());
        std::fflush(out_);
    }

    bool print_;
    std::FILE* out_;
};

} // namespace app
