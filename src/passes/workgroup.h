// Workgroup size of every 1D pass, passed to the shaders as WF_WORKGROUP_SIZE. 64 is a
// multiple of the usual subgroup sizes (4-16 on lavapipe, 32 on NVIDIA, 32 or 64 on AMD), so
// no subgroup runs partly empty; the shaders do not need it (docs/architecture.md, Subgroups).
#pragma once
#include <cstdint>

namespace wf {
constexpr uint32_t kWorkgroupSize = 64;
// vkCmdDispatch's guaranteed minimum of maxComputeWorkGroupCount[0].
constexpr uint32_t kMaxGroupsX = 65535;
} // namespace wf
