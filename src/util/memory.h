// memory.h - resident memory of this process or another, as the kernel counts it
// (/proc/PID/status), for --stats and for the CAD load's process tree. Plain C++, Linux.
#pragma once

#include <cstdint>
#include <sys/types.h>

namespace util {

// VmRSS: the pages resident now, in bytes; 0 where the process is gone or /proc unreadable.
// pid 0: this process.
uint64_t residentBytes(pid_t pid = 0);

// VmHWM: the most that were ever resident at once, in bytes; 0 likewise.
uint64_t peakResidentBytes(pid_t pid = 0);

// Bytes as whole mebibytes, rounded to nearest, for JSON and messages.
inline uint64_t mebibytes(uint64_t bytes) {
    return (bytes + (uint64_t(1) << 19)) >> 20;
}

} // namespace util
