// flag_docs.h - the manual page and the bash completion, written from idview's own flag
// table (app/cli_flags.h) and registries by idview-docs (docs_main.cpp), so that they say
// what the program parses. data/idview.1 and data/idview.bash-completion are its output,
// checked against a fresh run by the test `manual_current`.
#pragma once

#include <string>
#include <vector>

#include "app/cli_flags.h"

namespace docs {

// What a flag's value completes to: words, a model file, any file, a folder, or nothing (a
// number, a pixel, a colour to type).
struct ValueCompletion {
    enum class Kind { Words, ModelFile, File, Folder, Typed } kind = Kind::Typed;
    std::vector<std::string> words; // Kind::Words
};
ValueCompletion valueCompletion(const app::Flag& flag);

// The model files' extensions, lower and upper case: "gltf|glb|...|GLTF|GLB|...".
std::string modelExtensionPattern();

// idview.1 in roff (man(7)).
std::string manualPage();
// The bash completion, a function _idview bound to idview.
std::string bashCompletion();

} // namespace docs
