// gltf_parse.cpp - a .gltf/.glb's bytes to a tinygltf model, refused in one line where the
// file is not glTF 2.0, is damaged, needs an extension idview lacks, or names a file outside
// its folder (gltf_detail.h).
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

#include "scene/gltf/gltf_detail.h"

namespace scene::gltf {

namespace fs = std::filesystem;

// tinygltf takes the length as unsigned int; nothing this size is a sensible CAD part list.
constexpr uint64_t kMaxFileBytes = uint64_t(1) << 31;

std::vector<unsigned char> readFileBytes(const std::string& path) {
    std::error_code ec;
    if (!fs::exists(path, ec)) throw Bad("file not found");
    if (!fs::is_regular_file(path, ec)) throw Bad("not a regular file");
    uint64_t size = fs::file_size(path, ec);
    if (ec) throw Bad("cannot read the file size: " + ec.message());
    if (size > kMaxFileBytes) throw Bad("file too large (" + std::to_string(size) + " bytes)");
    std::ifstream in(path, std::ios::binary);
    std::vector<unsigned char> bytes(size);
    if (!in || !in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(size)))
        throw Bad("cannot read the file");
    return bytes;
}

// tinygltf messages span lines and may quote file content: make them one printable line.
std::string oneLine(const std::string& text) {
    std::string out;
    for (char c : text) {
        bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
        if (space && (out.empty() || out.back() == ' ')) continue;
        if (c == '\n' && out.size() >= 2 && out.back() != ';')
            out += "; ";
        else
            out += (space || (unsigned char)c < 0x20 || c == 0x7f) ? ' ' : c;
    }
    while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
    if (out.size() > 300) out = out.substr(0, 297) + "...";
    return out.empty() ? "unknown error" : out;
}

// What an old file's message suggests: a converter that upgrades glTF 1.0 (and its binary
// container) to 2.0.
constexpr const char* kConvertHint = "; convert it, e.g. with Cesium's gltf-pipeline";

// "<major>.<minor>" at the start of a version string (glTF's pattern is ^[0-9]+\.[0-9]+$;
// real 1.0 files say "1.0.2"), or -1 for the major number when there is none.
std::pair<long, long> versionNumbers(const std::string& version) {
    const char* begin = version.c_str();
    char* end = nullptr;
    if (!std::isdigit((unsigned char)*begin)) return {-1, 0};
    long major = std::strtol(begin, &end, 10);
    if (*end != '.' || !std::isdigit((unsigned char)end[1])) return {-1, 0};
    return {major, std::strtol(end + 1, nullptr, 10)};
}

// glTF 2.0, 3.2: a minor version is compatible, another major one is not; minVersion, when
// present, names the version the file cannot be read without.
void checkVersion(const tinygltf::Asset& asset) {
    const std::string version = asset.version.empty() ? "" : oneLine(asset.version);
    const long major = versionNumbers(asset.version).first;
    if (major < 0) throw Bad("asset.version '" + version + "' is not a glTF version");
    if (major != 2)
        throw Bad("glTF " + version + " is not supported (idview reads glTF 2.0" +
                  (major < 2 ? kConvertHint : "") + ")");
    if (asset.minVersion.empty()) return;
    const std::string minVersion = oneLine(asset.minVersion);
    auto [needMajor, needMinor] = versionNumbers(asset.minVersion);
    if (needMajor < 0) throw Bad("asset.minVersion '" + minVersion + "' is not a glTF version");
    if (needMajor != 2 || needMinor > 0)
        throw Bad("the file needs glTF " + minVersion +
                  " (asset.minVersion); idview reads glTF 2.0");
}

// The folder of the model: the only place external buffers and images are read from. The
// check is lexical (after tinygltf's percent-decoding): symbolic links inside the folder are
// followed wherever they point, since only the folder's owner can make them (and git-annex or
// DVC checkouts are built from them), while the file's own text cannot escape.
struct ModelFolder {
    std::string dir;     // as tinygltf joins it: the model's parent path, "" for the cwd
    std::string refusal; // the first URI refused, with the reason
    const tinygltf::Asset* asset = nullptr; // parsed before any buffer or image
};

// Why a percent-decoded, non-data URI may not be read, or "" when it names a file inside the
// model's folder: not an absolute path or a URL, and no ".." that climbs above the folder.
std::string whyRefused(const std::string& uri) {
    if (uri.find('\0') != std::string::npos) return "contains a NUL byte";
    if (!uri.empty() && uri[0] == '/') return "is an absolute path";
    size_t colon = uri.find(':');
    if (colon != std::string::npos && colon > 0 && std::isalpha((unsigned char)uri[0]) &&
        std::all_of(uri.begin(), uri.begin() + ptrdiff_t(colon), [](char c) {
            return std::isalnum((unsigned char)c) || c == '+' || c == '-' || c == '.';
        }))
        return "is a URL, not a relative path";
    int depth = 0;
    for (const auto& segment : fs::path(uri)) {
        if (segment == "..") {
            if (--depth < 0) return "points outside the model's folder";
        } else if (segment != "." && !segment.empty()) {
            ++depth;
        }
    }
    return "";
}

// tinygltf's file callbacks, replaced so that a URI can only name a regular file of sane
// size (never a device or a pipe) inside the model's folder, and no shell-style path
// expansion happens. tinygltf asks ExpandFilePath about "<dir>/<uri>" before it looks at a
// file, so a refused URI is never opened, nor even looked up. Its second try, "./<uri>" in
// the working directory, is refused without a word (the file is simply not found).
bool fileExists(const std::string& path, void*) {
    std::error_code ec;
    return !path.empty() && fs::is_regular_file(path, ec);
}
std::string expandInsideFolder(const std::string& path, void* user) {
    ModelFolder& folder = *static_cast<ModelFolder*>(user);
    try {
        checkVersion(*folder.asset); // a file of another version has no files read either
    } catch (const Bad&) {
        return "";
    }
    const std::string prefix =
        folder.dir.empty() || folder.dir.back() == '/' ? folder.dir : folder.dir + "/";
    if (path.compare(0, prefix.size(), prefix) != 0) return "";
    const std::string uri = path.substr(prefix.size());
    // A data: URI tinygltf cannot decode (say an unusual image type) is no file either.
    if (uri.rfind("data:", 0) == 0) return "";
    if (std::string why = whyRefused(uri); !why.empty()) {
        if (folder.refusal.empty())
            folder.refusal = "uri '" + oneLine(uri) + "' " + why +
                             " (idview reads only files inside the model's folder, and data: URIs)";
        return "";
    }
    // What is opened is what was checked: "sub/../a.bin" is "a.bin" even if sub is a link.
    return (fs::path(folder.dir) / uri).lexically_normal().string();
}
// nlohmann::json's parse errors (through tinygltf) read "[json.exception.parse_error.101]
// parse error at line 2, column 1: syntax error while parsing value - ...": said in words,
// with the place; other messages pass unchanged.
std::string jsonReason(const std::string& message) {
    if (message.find("json.exception") == std::string::npos) return message;
    const size_t at = message.find(" at line ");
    const size_t colon = message.find(':', at);
    const std::string where = at == std::string::npos || colon == std::string::npos
                                  ? std::string()
                                  : message.substr(at, colon - at);
    return "not valid JSON text: it breaks off or is malformed" + where;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void*) {
    try {
        *out = readFileBytes(path);
        return true;
    } catch (const std::exception& e) {
        if (err) *err += "cannot read '" + path + "': " + e.what();
        return false;
    }
}
bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "writing is not supported";
    return false;
}

// Textures are not shown, so images are neither decoded nor kept.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

uint32_t readLe32(const unsigned char* p) {
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// Checks the GLB container before tinygltf sees it, for clear messages on truncated files.
void checkGlbHeader(std::span<const unsigned char> bytes) {
    if (bytes.size() < 20)
        throw Bad("truncated GLB file (" + std::to_string(bytes.size()) + " bytes)");
    const uint32_t version = readLe32(bytes.data() + 4);
    if (version == 1)
        throw Bad(std::string("binary glTF 1.0 (GLB version 1) is not supported (idview reads "
                              "glTF 2.0") +
                  kConvertHint + ")");
    if (version != 2) throw Bad("unsupported GLB version " + std::to_string(version));
    uint64_t length = readLe32(bytes.data() + 8), jsonLength = readLe32(bytes.data() + 12);
    if (length > bytes.size())
        throw Bad("truncated GLB file: header says " + std::to_string(length) +
                  " bytes, file has " + std::to_string(bytes.size()));
    if (readLe32(bytes.data() + 16) != 0x4E4F534A) throw Bad("GLB file without a JSON chunk");
    if (20 + jsonLength > length) throw Bad("truncated GLB file: JSON chunk runs past the end");
}

bool hasExtension(const std::string& name, const char* ext) {
    return name.size() >= 4 && name.compare(name.size() - 4, 4, ext) == 0;
}

bool isHarmlessExtension(const std::string& ext) {
    // Extensions that change only looks we do not render; any other required one changes the
    // geometry or its encoding (Draco, meshopt, quantization), so we must refuse the file.
    static const char* const harmless[] = {
        "KHR_materials_pbrSpecularGlossiness",
        "KHR_materials_unlit",
        "KHR_texture_transform",
        "KHR_materials_emissive_strength",
        "KHR_lights_punctual",
        "KHR_texture_basisu",
        "EXT_texture_webp",
    };
    for (const char* h : harmless)
        if (ext == h) return true;
    return false;
}

void checkRequiredExtensions(const std::vector<std::string>& required) {
    for (const std::string& ext : required)
        if (!isHarmlessExtension(ext))
            throw Bad("requires the unsupported extension " + oneLine(ext));
}

// The names in the first "extensionsRequired": [...] of a JSON text, found without a JSON
// parser; only used to explain a file that tinygltf has already refused.
std::vector<std::string> requiredExtensionsInText(std::string_view json) {
    std::vector<std::string> names;
    const std::string_view key = "\"extensionsRequired\"";
    size_t at = json.find(key);
    if (at == std::string_view::npos) return names;
    size_t open = json.find('[', at), end = json.find(']', at);
    if (open == std::string_view::npos || end == std::string_view::npos || end < open) return names;
    std::string_view list = json.substr(open + 1, end - open - 1);
    for (size_t q = list.find('"'); q != std::string_view::npos; q = list.find('"', q + 1)) {
        size_t close = list.find('"', q + 1);
        if (close == std::string_view::npos) break;
        names.emplace_back(list.substr(q + 1, close - q - 1));
        q = close;
    }
    return names;
}

tinygltf::Model parse(std::span<const unsigned char> bytes, const std::string& name,
                      std::vector<std::string>& warnings) {
    if (bytes.empty()) throw Bad("file is empty");
    if (bytes.size() > kMaxFileBytes) throw Bad("file too large");
    bool binary = bytes.size() >= 4 && std::equal(bytes.begin(), bytes.begin() + 4, "glTF");
    if (!binary && (hasExtension(name, ".glb") || hasExtension(name, ".GLB")))
        throw Bad("not a GLB file (wrong magic)");
    if (binary) checkGlbHeader(bytes);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    tinygltf::Model model;
    model.asset.version.clear(); // tinygltf's default is "2.0": tell a missing one apart
    ModelFolder folder{fs::path(name).parent_path().string(), "", &model.asset};
    loader.SetFsCallbacks({fileExists, expandInsideFolder, readWholeFile, refuseWrite, &folder});
    std::string err, warn;
    auto length = static_cast<unsigned int>(bytes.size());
    bool ok =
        binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), length, folder.dir)
               : loader.LoadASCIIFromString(&model, &err, &warn,
                                            reinterpret_cast<const char*>(bytes.data()), length,
                                            folder.dir);
    // tinygltf reads the asset before anything else, and refuses a file without an
    // asset.version string in words of its own; its errors on another version's file would
    // only confuse, so the version is checked first.
    if (!ok && err.find("\"asset\" object not found") != std::string::npos)
        throw Bad(std::string("asset.version is missing or not a string: not a glTF 2.0 file "
                              "(idview reads glTF 2.0") +
                  kConvertHint + ")");
    if (ok || !model.asset.version.empty()) checkVersion(model.asset);
    if (!folder.refusal.empty()) throw Bad(folder.refusal);
    if (!ok) {
        // A Draco file fails in tinygltf (its accessors have no bufferView) before we see
        // extensionsRequired, so look for the real reason in the text first.
        std::string_view json(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        if (binary) json = json.substr(20, readLe32(bytes.data() + 12));
        checkRequiredExtensions(requiredExtensionsInText(json));
        throw Bad(err.empty() ? "tinygltf could not parse the file" : jsonReason(oneLine(err)));
    }
    if (!warn.empty()) warnings.push_back("tinygltf: " + oneLine(warn));
    return model;
}

} // namespace scene::gltf
