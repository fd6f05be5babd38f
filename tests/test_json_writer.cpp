// test_json_writer.cpp - util::JsonWriter: strings escaped as JSON requires and UTF-8 left
// alone, doubles that read back bit for bit, NaN and infinity as null, the fixed and
// significant formats, nesting and layout, and every misuse refused.
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "util/json_writer.h"

namespace {

using util::JsonWriter;

// One value as a whole document.
template <typename T>
std::string one(const T& v) {
    JsonWriter json;
    json.value(v);
    return json.text();
}

TEST(JsonWriter, StringsEscapeQuotesBackslashesAndControlCharacters) {
    EXPECT_EQ(one("bolt M10 #1"), "\"bolt M10 #1\"");
    EXPECT_EQ(one("say \"hi\""), R"("say \"hi\"")");
    EXPECT_EQ(one("C:\\parts\\"), R"("C:\\parts\\")");
    // Every control character as \u00XX (newline and tab included), and DEL.
    EXPECT_EQ(one("a\nb\tc\x01\x1f\x7f"), R"("a\u000ab\u0009c\u0001\u001f\u007f")");
    EXPECT_EQ(one(std::string("nul\0in", 6)), R"("nul\u0000in")");
    // Bytes of 0x80 and above are UTF-8 and pass untouched: é, µ, Ø, a CJK character.
    EXPECT_EQ(one("\xc3\xa9 \xc2\xb5m \xc3\x98 \xe9\x83\xa8"),
              "\"\xc3\xa9 \xc2\xb5m \xc3\x98 \xe9\x83\xa8\"");
    EXPECT_EQ(one("a\"b\\c\n\x01\x7f\xc3\xa9"), "\"a\\\"b\\\\c\\u000a\\u0001\\u007f\xc3\xa9\"");
    EXPECT_EQ(one(std::string()), "\"\"");
    // Keys go through the same escaping.
    JsonWriter json;
    json.beginObject().member("a\"b", 1).endObject();
    EXPECT_EQ(json.text(), R"({"a\"b":1})");
}

TEST(JsonWriter, DoublesReadBackExactly) {
    const double values[] = {0.1,
                             458005.5,
                             -17.89811369191,
                             1.0 / 3.0,
                             std::numbers::pi,
                             6.02214076e23,
                             -2.220446049250313e-16,
                             DBL_MIN,
                             std::numeric_limits<double>::denorm_min(),
                             DBL_MAX,
                             -DBL_MAX,
                             123456789012345678.0};
    for (double v : values) {
        const std::string text = one(v);
        char* end = nullptr;
        const double back = std::strtod(text.c_str(), &end);
        EXPECT_EQ(*end, '\0') << text;
        EXPECT_EQ(std::memcmp(&back, &v, sizeof v), 0) << text << " read back as " << back;
    }
    // The shortest form: no trailing digits a reader does not need.
    EXPECT_EQ(one(0.1), "0.1");
    EXPECT_EQ(one(5.0), "5");
    EXPECT_EQ(one(458005.5), "458005.5");
    EXPECT_EQ(one(2.5f), "2.5"); // a float is written as the double it is
}

TEST(JsonWriter, NanAndInfinityAreNullInEveryFormat) {
    for (double v : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
        EXPECT_EQ(one(v), "null");
        EXPECT_EQ(one(util::Fixed{v, 3}), "null");
        EXPECT_EQ(one(util::Significant{v, 6}), "null");
    }
    JsonWriter json;
    json.value(glm::dvec3(1.0, std::nan(""), -HUGE_VAL));
    EXPECT_EQ(json.text(), "[1,null,null]");
}

TEST(JsonWriter, FixedAndSignificantFormats) {
    EXPECT_EQ(one(util::Fixed{1.23456, 3}), "1.235");
    EXPECT_EQ(one(util::Fixed{0.0, 4}), "0.0000");
    EXPECT_EQ(one(util::Fixed{12324.0, 1}), "12324.0");
    EXPECT_EQ(one(util::Fixed{2.5, 0}), "2");
    // Nine significant digits read a float back exactly.
    const float depth = 0.763167322f;
    const std::string text = one(util::Significant{depth, 9});
    EXPECT_EQ(text, "0.763167322");
    EXPECT_EQ(std::strtof(text.c_str(), nullptr), depth);
    EXPECT_EQ(one(util::Significant{0.1031031031, 6}), "0.103103");
    EXPECT_EQ(one(util::Significant{0.0, 6}), "0");
}

TEST(JsonWriter, IntegersBoolsNullAndOptionals) {
    EXPECT_EQ(one(std::numeric_limits<uint64_t>::max()), "18446744073709551615");
    EXPECT_EQ(one(-42), "-42");
    EXPECT_EQ(one(size_t(7)), "7");
    EXPECT_EQ(one(true), "true");
    EXPECT_EQ(one(false), "false");
    EXPECT_EQ(one(std::optional<uint32_t>()), "null");
    EXPECT_EQ(one(std::optional<uint32_t>(3)), "3");
    JsonWriter json;
    json.null();
    EXPECT_EQ(json.text(), "null");
}

TEST(JsonWriter, NestingAndCommas) {
    JsonWriter json;
    json.beginObject()
        .member("name", "bracket")
        .array("parts", std::vector<uint32_t>{})
        .array("ids", std::vector<uint32_t>{4, 5, 6})
        .beginArray("children")
        .beginObject()
        .member("x", 1)
        .endObject()
        .beginObject()
        .endObject()
        .beginArray()
        .endArray()
        .endArray()
        .beginObject("box")
        .member("min", glm::dvec3(0.5, -1.0, 2.0))
        .endObject()
        .member("closed", false)
        .endObject();
    EXPECT_EQ(json.text(),
              R"({"name":"bracket","parts":[],"ids":[4,5,6],"children":[{"x":1},{},[]],)"
              R"("box":{"min":[0.5,-1,2]},"closed":false})");
}

// The benchmark's layout: a line break goes after the comma, before the next item or end.
TEST(JsonWriter, LineBreaksGoBetweenTokens) {
    JsonWriter json;
    json.beginObject().member("a", 1).newline(1).beginArray("rows");
    for (int i = 0; i < 2; ++i) json.newline(2).beginObject().member("i", i).endObject();
    json.newline(1).endArray().endObject();
    EXPECT_EQ(json.text(), "{\"a\":1,\n \"rows\":[\n  {\"i\":0},\n  {\"i\":1}\n ]}");
}

TEST(JsonWriter, MisuseIsRefused) {
    auto refused = [](const std::function<void(JsonWriter&)>& misuse, const char* words) {
        JsonWriter json;
        try {
            misuse(json);
            ADD_FAILURE() << "accepted: " << words;
        } catch (const std::logic_error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    refused([](JsonWriter& j) { j.key("x"); }, "a key 'x' outside an object");
    refused([](JsonWriter& j) { j.beginArray().key("x"); }, "a key 'x' outside an object");
    refused([](JsonWriter& j) { j.beginObject().value(1); }, "a value without a key");
    refused([](JsonWriter& j) { j.beginObject().member("a", 1).beginArray(); },
            "a value without a key");
    refused([](JsonWriter& j) { j.beginObject().key("a").key("b"); }, "after a key without");
    refused([](JsonWriter& j) { j.beginObject().key("a").endObject(); }, "without its value");
    refused([](JsonWriter& j) { j.beginObject().endArray(); }, "end of an array that is not open");
    refused([](JsonWriter& j) { j.beginArray().endObject(); }, "end of an object that is not open");
    refused([](JsonWriter& j) { j.endObject(); }, "end of an object that is not open");
    refused([](JsonWriter& j) { j.beginObject().endObject().endObject(); }, "not open");
    refused([](JsonWriter& j) { j.value(1).value(2); }, "a second top-level value");
    refused([](JsonWriter& j) { j.beginObject().endObject().beginArray(); }, "second top-level");
    refused([](JsonWriter& j) { (void)j.text(); }, "no value written");
    refused([](JsonWriter& j) { (void)j.beginObject().beginArray("a").text(); }, "left open");
    refused([](JsonWriter& j) { j.value(util::Fixed{1.0, 40}); }, "40 decimals");
    refused([](JsonWriter& j) { j.value(util::Significant{1.0, 0}); }, "0 significant digits");
}

} // namespace
