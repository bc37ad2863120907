#include "app/reports/host_memory.h"

#include <fstream>
#include <string>

namespace wf {

std::uint64_t peakHostMemoryBytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0)
            return std::stoull(line.substr(6)) * 1024; // "VmHWM:  123456 kB"
    return 0;
}

} // namespace wf
