// json.h - the one JSON string escaper every JSON line idview prints goes through.
#pragma once

#include <string>

namespace app {

// `text` as a JSON string literal, quotes included: '"' and '\' get a backslash, control
// characters (below 0x20, and 0x7f) become \u00XX; other bytes, UTF-8 included, pass as they
// are.
std::string jsonString(const std::string& text);

} // namespace app
