// memory.cpp - VmRSS and VmHWM read from /proc (memory.h).
#include "util/memory.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace util {
namespace {

// The value of `field` ("VmRSS:", "VmHWM:") in /proc/PID/status, which the kernel gives in kB.
uint64_t statusKilobytes(pid_t pid, const char* field) {
    const std::string path =
        pid == 0 ? std::string("/proc/self/status") : "/proc/" + std::to_string(pid) + "/status";
    std::FILE* file = std::fopen(path.c_str(), "r");
    if (!file) return 0;
    char line[256];
    unsigned long long kilobytes = 0;
    const size_t length = std::strlen(field);
    while (std::fgets(line, sizeof line, file))
        if (std::strncmp(line, field, length) == 0) {
            std::sscanf(line + length, "%llu", &kilobytes);
            break;
        }
    std::fclose(file);
    return kilobytes * 1024;
}

} // namespace

uint64_t residentBytes(pid_t pid) {
    return statusKilobytes(pid, "VmRSS:");
}

uint64_t peakResidentBytes(pid_t pid) {
    return statusKilobytes(pid, "VmHWM:");
}

} // namespace util
