// mapped_file.cpp - the read-only mapping behind mapped_file.h.
#include "util/mapped_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <stdexcept>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

namespace util {

namespace {

std::runtime_error failure(const std::string& path, const char* what) {
    return std::runtime_error(path + ": cannot " + what + " (" + std::strerror(errno) + ")");
}

} // namespace

// The file is mapped over an anonymous zeroed area one page longer, so that the byte after
// its last one reads as zero even when its size is a whole number of pages (a plain mapping
// would fault there).
MappedFile::MappedFile(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw failure(path, "open it");
    struct stat info {};
    if (::fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
        const auto error = S_ISREG(info.st_mode) ? failure(path, "read its size")
                                                 : std::runtime_error(path + ": not a file");
        ::close(fd);
        throw error;
    }
    const size_t page = size_t(::sysconf(_SC_PAGESIZE));
    size_ = size_t(info.st_size);
    mapped_ = (size_ + page - 1) / page * page + page;
    void* area = ::mmap(nullptr, mapped_, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (area == MAP_FAILED) {
        ::close(fd);
        throw failure(path, "reserve memory to map it");
    }
    if (size_ > 0 && ::mmap(area, size_, PROT_READ, MAP_PRIVATE | MAP_FIXED, fd, 0) == MAP_FAILED) {
        const auto error = failure(path, "map it");
        ::munmap(area, mapped_);
        ::close(fd);
        throw error;
    }
    ::close(fd);
    data_ = static_cast<char*>(area);
}

MappedFile::~MappedFile() {
    if (data_) ::munmap(data_, mapped_);
}

} // namespace util
