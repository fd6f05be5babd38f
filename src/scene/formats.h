// formats.h - the model formats idview reads, listed once: each with its name, its file
// extensions and the reader that takes it. Every list of formats people see (the --model
// help, the viewer's file chooser, its open hint, the drop refusal) is made from this table,
// and every model file passes checkModelFile, by its content, before any reader sees it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace scene {

enum class Reader { Gltf, Step, Iges, Brep, Stl };

struct ModelFormat {
    std::string_view name;                    // "glTF", "STEP", ...
    std::vector<std::string_view> extensions; // lower case, with the dot; any case matches
    Reader reader;
};

// The table, in the order people see it.
const std::vector<ModelFormat>& modelFormats();

// The format a file name's extension names, in any case; null for none.
const ModelFormat* formatOfName(const std::string& path);
// True for the formats Open CASCADE reads as B-reps (STEP, IGES, BREP).
bool isBrepReader(Reader reader);

// Every extension of `formats`, joined by `separator`: ".gltf .glb .step ...".
std::string extensionList(const std::vector<const ModelFormat*>& formats,
                          std::string_view separator = " ");
std::string extensionList(std::string_view separator = " ");
// "glTF (.gltf, .glb), STEP (.step, .stp), ...": for help texts and refusals.
std::string formatList();

// The format of the file at `path`, by its extension, once its content agrees: throws
// ModelError "<path>: <reason>" (one line) for a missing file, a folder, an empty or unreadable
// file, a name of no format idview reads, or content that is not what the extension says (a
// GLB without its magic, a STEP file without its ISO-10303-21 header, an STL file that is
// neither ASCII 'solid' text nor a binary STL of its size, ...).
const ModelFormat& checkModelFile(const std::string& path);

} // namespace scene
