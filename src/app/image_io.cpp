// image_io.cpp - PNG through stb_image_write (libstb), ID images byte by byte so the file is
// little-endian whatever the host.
#include "app/image_io.h"

#include <cstring>
#include <fstream>
#include <stdexcept>

#include <stb_image_write.h>

namespace app {

void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba) {
    if (rgba.size() != size_t(width) * height * 4)
        throw std::runtime_error("writePng: pixel count does not match the size");
    if (!stbi_write_png(path.c_str(), int(width), int(height), 4, rgba.data(), int(width * 4)))
        throw std::runtime_error("cannot write PNG '" + path + "': " + std::strerror(errno));
}

void writeIdImage(const std::string& path, const std::vector<uint32_t>& ids) {
    std::vector<uint8_t> bytes(ids.size() * 4);
    for (size_t i = 0; i < ids.size(); ++i)
        for (int b = 0; b < 4; ++b) bytes[4 * i + b] = uint8_t(ids[i] >> (8 * b));
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    if (!out)
        throw std::runtime_error("cannot write ID image '" + path + "': " + std::strerror(errno));
}

std::vector<uint32_t> readIdImage(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
    // istreambuf_iterator reads to the end without setting the stream's eofbit.
    if (!in.is_open() || in.bad() || bytes.size() % 4 != 0)
        throw std::runtime_error("cannot read ID image '" + path + "'");
    std::vector<uint32_t> ids(bytes.size() / 4);
    for (size_t i = 0; i < ids.size(); ++i)
        for (int b = 0; b < 4; ++b) ids[i] |= uint32_t(bytes[4 * i + b]) << (8 * b);
    return ids;
}

} // namespace app
