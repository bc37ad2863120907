// Workgroup size of every 1D pass, passed to the shaders as WF_WORKGROUP_SIZE. 64 is a
// multiple of every subgroup size in use (8 on lavapipe, 32 on NVIDIA, 64 on AMD).
#pragma once
#include <cstdint>

namespace wf {
constexpr uint32_t kWorkgroupSize = 64;
// vkCmdDispatch's guaranteed minimum of maxComputeWorkGroupCount[0].
constexpr uint32_t kMaxGroupsX = 65535;
} // namespace wf
