// cache_file.cpp - the cache folder, whole-file reads and atomic writes (cache_file.h).
#include "util/cache_file.h"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

namespace util {

namespace fs = std::filesystem;

fs::path cacheFolder() {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && fs::path(xdg).is_absolute())
        return fs::path(xdg) / "idview";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".cache" / "idview";
    return {};
}

// One read: entries of large models run to hundreds of megabytes.
std::optional<std::string> readWholeFile(const fs::path& file) {
    std::error_code ec;
    const uintmax_t size = fs::file_size(file, ec);
    std::ifstream in(file, std::ios::binary);
    if (ec || !in) return std::nullopt;
    std::string bytes(size_t(size), '\0');
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (size_t(in.gcount()) != bytes.size()) return std::nullopt;
    return bytes;
}

std::string writeFileAtomically(const fs::path& file, const std::vector<std::string_view>& parts) {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    if (ec) return file.parent_path().string() + ": " + ec.message();
    // Unique per process and call, in the file's folder so that the rename stays atomic.
    static std::atomic<uint32_t> serial{0};
    fs::path temporary = file;
    temporary += ".tmp" + std::to_string(::getpid()) + "_" + std::to_string(serial++);
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        for (std::string_view part : parts) out.write(part.data(), std::streamsize(part.size()));
        out.close();
        if (!out) {
            fs::remove(temporary, ec);
            return temporary.string() + ": write failed";
        }
    }
    fs::rename(temporary, file, ec);
    if (ec) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        return file.string() + ": " + ec.message();
    }
    return {};
}

} // namespace util
