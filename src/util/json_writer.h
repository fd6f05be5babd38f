// json_writer.h - the one way idview writes JSON: every line it prints (picks, face and edge
// reports, measurements, --stats, --tree) and the benchmark's file. Escaping and number
// formats live here alone. Misuse (a key outside an object, a value without its key, an end
// that does not match, a document left open) throws std::logic_error: a bug in idview,
// never a malformed line on stdout.
#pragma once

#include <concepts>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

namespace util {

// A number written with `decimals` digits after the point ("%.*f"): what the benchmark's
// milliseconds and counts have always printed, so that columns line up and readers can
// count on the digits.
struct Fixed {
    double value;
    int decimals;
};

// A number written with `digits` significant digits ("%.*g"), for values whose output has
// that form (a float's 9 digits read back exactly; a tolerance needs 6).
struct Significant {
    double value;
    int digits;
};

class JsonWriter {
  public:
    JsonWriter& beginObject() { return beginContainer(Open::Object); }
    JsonWriter& endObject() { return endContainer(Open::Object); }
    JsonWriter& beginArray() { return beginContainer(Open::Array); }
    JsonWriter& endArray() { return endContainer(Open::Array); }
    // The same, as the value of member `name`.
    JsonWriter& beginObject(std::string_view name) { return key(name).beginObject(); }
    JsonWriter& beginArray(std::string_view name) { return key(name).beginArray(); }

    // The name of the next member of the innermost object.
    JsonWriter& key(std::string_view name);

    // Strings: '"' and '\' get a backslash, control characters (below 0x20, and 0x7f)
    // become \u00XX; every other byte, UTF-8 included, passes as it is.
    JsonWriter& value(std::string_view text);
    JsonWriter& value(const char* text) { return value(std::string_view(text)); }
    JsonWriter& value(const std::string& text) { return value(std::string_view(text)); }
    JsonWriter& value(bool flag);
    template <std::integral T>
    requires(!std::same_as<T, bool>) JsonWriter& value(T number) {
        return raw(std::to_string(number));
    }
    // The shortest decimal that reads back as exactly `number` ("0.1", "458005.5"): a point
    // kilometres from the origin keeps its millimetres. JSON has no NaN or infinity, so
    // those (in every format) write null.
    JsonWriter& value(double number);
    JsonWriter& value(Fixed number);
    JsonWriter& value(Significant number);
    // [x,y,z], each as a double above.
    JsonWriter& value(const glm::dvec3& point);
    template <typename T>
    JsonWriter& value(const std::optional<T>& maybe) {
        return maybe ? value(*maybe) : null();
    }
    JsonWriter& null();
    JsonWriter& value(std::nullopt_t) { return null(); } // member("name", std::nullopt)

    // key(name).value(v): one member of the innermost object.
    template <typename T>
    JsonWriter& member(std::string_view name, const T& v) {
        return key(name).value(v);
    }
    // [v0,v1,...] as the value of member `name`.
    template <typename T>
    JsonWriter& array(std::string_view name, const std::vector<T>& values) {
        beginArray(name);
        for (const T& v : values) value(v);
        return endArray();
    }

    // A line break and `indent` spaces before the next item (after its comma), for a
    // document read line by line (the benchmark's: one result a line). JSON allows white
    // space between any two tokens, so this never changes what a parser reads.
    JsonWriter& newline(int indent);

    // The finished document: one value, every object and array closed.
    const std::string& text() const;

  private:
    enum class Open : uint8_t { Object, Array };
    struct Level {
        Open kind;
        bool empty = true;       // no member or element yet: no comma before the next
        bool keyPending = false; // an object's key written, its value not yet
    };

    // Before a value: the comma, the pending line break, and the checks that a value may
    // stand here.
    void beforeValue(const char* what);
    JsonWriter& beginContainer(Open kind);
    JsonWriter& endContainer(Open kind);
    JsonWriter& raw(std::string_view token);
    void writeString(std::string_view text);

    std::string text_;
    std::string pendingSpace_;
    std::vector<Level> open_;
    bool done_ = false; // the top-level value is complete
};

} // namespace util
