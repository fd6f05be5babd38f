// image_io.h - writing the colour image as PNG and the part-ID image as raw uint32 values.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace app {

// RGBA8 pixels, row-major, top row first. Throws std::runtime_error naming the file.
void writePng(const std::string& path, uint32_t width, uint32_t height,
              const std::vector<uint8_t>& rgba);

// width * height little-endian uint32 values, row-major, top row first.
void writeIdImage(const std::string& path, const std::vector<uint32_t>& ids);
std::vector<uint32_t> readIdImage(const std::string& path);

} // namespace app
