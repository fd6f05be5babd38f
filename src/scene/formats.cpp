// formats.cpp - the table of model formats and the check of a file's content against its
// extension (formats.h): a few bytes of its head, and for binary STL its size.
#include "scene/formats.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "scene/scene.h" // ModelError
#include "scene/stl/stl_loader.h"

namespace scene {
namespace {

namespace fs = std::filesystem;
using Refusal = std::optional<std::string>;

// What is read of a file's head to tell its format: every signature below lies within it.
constexpr size_t kHeadBytes = 4096;

std::string lowercase(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return out;
}

// The head past a UTF-8 byte order mark and white space.
std::string_view trimmedStart(std::string_view head) {
    if (head.starts_with("\xEF\xBB\xBF")) head.remove_prefix(3);
    while (!head.empty() && std::isspace(static_cast<unsigned char>(head.front())))
        head.remove_prefix(1);
    return head;
}

Refusal refuseGltf(std::string_view head, uintmax_t) {
    // loadGltf tells GLB from JSON by the magic, whichever of the two extensions it has.
    if (head.starts_with("glTF") || trimmedStart(head).starts_with("{")) return std::nullopt;
    return "not a glTF file (neither a GLB's 'glTF' magic nor JSON text)";
}

Refusal refuseStep(std::string_view head, uintmax_t) {
    if (head.find("ISO-10303-21") != std::string_view::npos) return std::nullopt;
    return "not a STEP file (no 'ISO-10303-21' header)";
}

// An IGES file is 80-column records, the first one of its start section: 'S' in column 73.
Refusal refuseIges(std::string_view head, uintmax_t) {
    const size_t end = head.find_first_of("\r\n");
    const std::string_view first = head.substr(0, end);
    if (first.size() >= 73 && first[72] == 'S') return std::nullopt;
    return "not an IGES file (its first record is no start record, 'S' in column 73)";
}

Refusal refuseBrep(std::string_view head, uintmax_t) {
    if (head.substr(0, 256).find("CASCADE Topology V") != std::string_view::npos)
        return std::nullopt;
    return "not a BREP file (no 'CASCADE Topology' header)";
}

// Binary STL by its size (isBinaryStl); ASCII STL: text that starts with "solid" (binary
// headers may too, so the size decides first).
Refusal refuseStl(std::string_view head, uintmax_t size) {
    if (isBinaryStl(head, size)) return std::nullopt;
    const bool text = head.find('\0') == std::string_view::npos;
    if (text && lowercase(trimmedStart(head).substr(0, 5)) == "solid") return std::nullopt;
    if (head.size() < 84)
        return "not an STL file (no ASCII 'solid' text, and too short for a binary STL's "
               "84-byte header)";
    return "not an STL file (no ASCII 'solid' text, and not a binary STL: its size is not "
           "84 + 50 bytes for each triangle its header counts)";
}

struct Entry {
    ModelFormat format;
    Refusal (*refuse)(std::string_view head, uintmax_t size);
};

const std::vector<Entry>& entries() {
    static const std::vector<Entry> table = {
        {{"glTF", {".gltf", ".glb"}, Reader::Gltf}, refuseGltf},
        {{"STEP", {".step", ".stp"}, Reader::Step}, refuseStep},
        {{"IGES", {".iges", ".igs"}, Reader::Iges}, refuseIges},
        {{"BREP", {".brep"}, Reader::Brep}, refuseBrep},
        {{"STL", {".stl"}, Reader::Stl}, refuseStl},
    };
    return table;
}

const Entry* entryOfName(const std::string& path) {
    const std::string ext = lowercase(fs::path(path).extension().string());
    for (const Entry& entry : entries())
        for (std::string_view known : entry.format.extensions)
            if (ext == known) return &entry;
    return nullptr;
}

// Why the file at `path` cannot be read at all, before its format is asked.
Refusal fileRefusal(const std::string& path) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) return std::string("file not found");
    if (fs::is_directory(status)) return std::string("a folder, not a file");
    if (!fs::is_regular_file(status)) return std::string("not a regular file");
    return std::nullopt;
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
    throw ModelError(path + ": " + why);
}

} // namespace

const std::vector<ModelFormat>& modelFormats() {
    static const std::vector<ModelFormat> formats = [] {
        std::vector<ModelFormat> out;
        for (const Entry& entry : entries()) out.push_back(entry.format);
        return out;
    }();
    return formats;
}

const ModelFormat* formatOfName(const std::string& path) {
    const Entry* entry = entryOfName(path);
    if (!entry) return nullptr;
    const size_t index = size_t(entry - entries().data());
    return &modelFormats()[index];
}

bool isBrepReader(Reader reader) {
    return reader == Reader::Step || reader == Reader::Iges || reader == Reader::Brep;
}

std::string extensionList(const std::vector<const ModelFormat*>& formats,
                          std::string_view separator) {
    std::string text;
    for (const ModelFormat* format : formats)
        for (std::string_view ext : format->extensions)
            text.append(text.empty() ? "" : separator).append(ext);
    return text;
}

std::string extensionList(std::string_view separator) {
    std::vector<const ModelFormat*> all;
    for (const ModelFormat& format : modelFormats()) all.push_back(&format);
    return extensionList(all, separator);
}

std::string formatList() {
    std::string text;
    for (const ModelFormat& format : modelFormats())
        text.append(text.empty() ? "" : ", ")
            .append(format.name)
            .append(" (")
            .append(extensionList({&format}, ", "))
            .append(")");
    return text;
}

const ModelFormat& checkModelFile(const std::string& path) {
    if (const Refusal why = fileRefusal(path)) refuse(path, *why);
    const Entry* entry = entryOfName(path);
    if (!entry) refuse(path, "not a file idview reads by its name; it reads " + formatList());
    std::ifstream in(path, std::ios::binary);
    if (!in) refuse(path, std::string("cannot open it: ") + std::strerror(errno));
    std::string head(kHeadBytes, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    if (head.empty()) refuse(path, "the file is empty");
    std::error_code ec;
    const uintmax_t size = fs::file_size(path, ec);
    if (ec) refuse(path, "cannot read the file size: " + ec.message());
    if (const Refusal why = entry->refuse(head, size)) refuse(path, *why);
    return *formatOfName(path);
}

} // namespace scene
