// mapped_file.h - a file mapped read-only into memory, never copied, with one zero byte
// readable just past its end, so that a scanner can stop on that byte instead of testing its
// position at every step (the STEP splitter's lexer, scene/step/). Plain C++ over POSIX mmap.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace util {

class MappedFile {
  public:
    // Throws std::runtime_error naming the file and the reason where it cannot be mapped.
    explicit MappedFile(const std::string& path);
    ~MappedFile();
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;

    // The file's bytes; text().data()[text().size()] is a readable zero byte.
    std::string_view text() const { return {data_, size_}; }

  private:
    char* data_ = nullptr;
    size_t size_ = 0;
    size_t mapped_ = 0; // the file's bytes rounded up to pages, plus one page
};

} // namespace util
