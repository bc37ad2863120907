// The driver's acceleration structures (VK_KHR_acceleration_structure): bottom levels over
// triangles or boxes, and one top level over their placements, built in one submit and kept
// for as long as the set lives. Knows nothing of scenes: the caller hands in the geometry by
// device address, and may free those buffers once the set exists.
#pragma once
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "gpu/buffer.h"

namespace wf {

class Context;

// One bottom level of one geometry. Triangles: 3 vertices per triangle, unindexed, three
// floats at the start of every 16 bytes (the layout of the scene's own Triangle entries, so
// that table uploads as it is). Boxes: VkAabbPositionsKHR, one per primitive.
struct BottomLevelInput {
    VkDeviceAddress data = 0;
    uint32_t primitiveCount = 0;
    bool triangles = true;
    bool opaque = true; // false: the hit group's any-hit shader sees every candidate
};

// One placement in the top level.
struct TopLevelInstance {
    VkTransformMatrixKHR worldFromObject{}; // rows of a 3x4 matrix
    uint32_t customIndex = 0;               // 24 bits: gl_InstanceCustomIndexEXT
    uint32_t hitGroup = 0;                  // shader binding table offset
    uint32_t bottomLevel = 0;               // index into the bottom-level inputs
};

class AccelerationStructureSet {
public:
    AccelerationStructureSet(const Context& context, const std::vector<BottomLevelInput>& bottom,
                             const std::vector<TopLevelInstance>& instances);
    ~AccelerationStructureSet();
    AccelerationStructureSet(const AccelerationStructureSet&) = delete;
    AccelerationStructureSet& operator=(const AccelerationStructureSet&) = delete;

    VkAccelerationStructureKHR topLevel() const { return topLevel_; }
    uint64_t bytes() const;       // every structure's storage (scratch and inputs excluded)
    double buildSeconds() const { return buildSeconds_; } // the submit, wall time

private:
    struct Built {
        Buffer storage;
        VkAccelerationStructureKHR handle = VK_NULL_HANDLE;
    };
    void release();

    const Context& context_;
    std::vector<Built> bottom_;
    Built top_;
    VkAccelerationStructureKHR topLevel_ = VK_NULL_HANDLE;
    double buildSeconds_ = 0.0;
};

} // namespace wf
