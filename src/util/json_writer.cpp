// json_writer.cpp - JSON tokens, their separators and the checks that keep a document well
// formed.
#include "util/json_writer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace util {
namespace {

[[noreturn]] void misuse(const std::string& what) {
    throw std::logic_error("JSON writer: " + what);
}

} // namespace

void JsonWriter::beforeValue(const char* what) {
    if (done_) misuse(std::string("a second top-level value (") + what + ")");
    if (!open_.empty()) {
        Level& level = open_.back();
        if (level.kind == Open::Object) {
            if (!level.keyPending) misuse(std::string("a value without a key (") + what + ")");
            level.keyPending = false;
        } else {
            if (!level.empty) text_ += ',';
            level.empty = false;
        }
    }
    text_ += pendingSpace_;
    pendingSpace_.clear();
}

JsonWriter& JsonWriter::raw(std::string_view token) {
    beforeValue("a number or literal");
    text_ += token;
    if (open_.empty()) done_ = true;
    return *this;
}

JsonWriter& JsonWriter::beginContainer(Open kind) {
    beforeValue(kind == Open::Object ? "an object" : "an array");
    text_ += kind == Open::Object ? '{' : '[';
    open_.push_back({kind});
    return *this;
}

JsonWriter& JsonWriter::endContainer(Open kind) {
    const char* name = kind == Open::Object ? "object" : "array";
    if (open_.empty() || open_.back().kind != kind)
        misuse(std::string("an end of an ") + name + " that is not open");
    if (open_.back().keyPending) misuse("an object closed after a key without its value");
    open_.pop_back();
    text_ += pendingSpace_;
    pendingSpace_.clear();
    text_ += kind == Open::Object ? '}' : ']';
    if (open_.empty()) done_ = true;
    return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
    if (open_.empty() || open_.back().kind != Open::Object)
        misuse("a key '" + std::string(name) + "' outside an object");
    Level& level = open_.back();
    if (level.keyPending) misuse("a key '" + std::string(name) + "' after a key without a value");
    if (!level.empty) text_ += ',';
    level.empty = false;
    text_ += pendingSpace_;
    pendingSpace_.clear();
    writeString(name);
    text_ += ':';
    level.keyPending = true;
    return *this;
}

void JsonWriter::writeString(std::string_view text) {
    text_ += '"';
    for (char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7f) {
            char code[8];
            std::snprintf(code, sizeof code, "\\u%04x", unsigned(byte));
            text_ += code;
            continue;
        }
        if (c == '"' || c == '\\') text_ += '\\';
        text_ += c;
    }
    text_ += '"';
}

JsonWriter& JsonWriter::value(std::string_view text) {
    beforeValue("a string");
    writeString(text);
    if (open_.empty()) done_ = true;
    return *this;
}

JsonWriter& JsonWriter::value(bool flag) {
    return raw(flag ? "true" : "false");
}

JsonWriter& JsonWriter::value(double number) {
    if (!std::isfinite(number)) return null();
    char text[32];
    const auto result = std::to_chars(text, text + sizeof text, number);
    return raw(std::string_view(text, size_t(result.ptr - text)));
}

JsonWriter& JsonWriter::value(Fixed number) {
    if (number.decimals < 0 || number.decimals > 17)
        misuse("a fixed number with " + std::to_string(number.decimals) + " decimals");
    if (!std::isfinite(number.value)) return null();
    char text[352]; // the longest double with its decimals: 309 digits, sign, point, 17 decimals
    std::snprintf(text, sizeof text, "%.*f", number.decimals, number.value);
    return raw(text);
}

JsonWriter& JsonWriter::value(Significant number) {
    if (number.digits < 1 || number.digits > 17)
        misuse("a number with " + std::to_string(number.digits) + " significant digits");
    if (!std::isfinite(number.value)) return null();
    char text[48];
    std::snprintf(text, sizeof text, "%.*g", number.digits, number.value);
    return raw(text);
}

JsonWriter& JsonWriter::value(const glm::dvec3& point) {
    return beginArray().value(point.x).value(point.y).value(point.z).endArray();
}

JsonWriter& JsonWriter::null() {
    return raw("null");
}

JsonWriter& JsonWriter::newline(int indent) {
    // Built piece by piece: GCC 12 warns (-Wrestrict) on "literal" + std::string here.
    pendingSpace_.assign(1, '\n');
    pendingSpace_.append(size_t(std::max(indent, 0)), ' ');
    return *this;
}

const std::string& JsonWriter::text() const {
    if (!done_) misuse(open_.empty() ? "no value written" : "a document left open");
    return text_;
}

} // namespace util
