// This process's peak resident memory, for --verbose and the JSON statistics.
#pragma once
#include <cstdint>

namespace wf {

// The kernel's high-water mark of resident memory (VmHWM), in bytes; 0 where it cannot be read.
std::uint64_t peakHostMemoryBytes();

} // namespace wf
