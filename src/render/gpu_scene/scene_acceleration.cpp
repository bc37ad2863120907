#include "render/gpu_scene/scene_acceleration.h"

#include <algorithm>
#include <map>

#include "errors.h"
#include "gpu/buffer.h"
#include "gpu/context.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/shader_variant.h"

namespace wf {
namespace {

constexpr VkBufferUsageFlags kBuildInput =
    VK_BUFFER_USAGE_ACCELERATION_STRUCTURE_BUILD_INPUT_READ_ONLY_BIT_KHR |
    VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT;

struct TriangleRange {
    uint32_t first = ~0u;
    uint32_t end = 0;
};

// The triangles under the tree rooted at pair entry `root`: a mesh's range is contiguous in
// the table (instance_bvh.h), so its leaves' lowest and highest triangles bound it.
TriangleRange rangeUnder(const std::vector<BvhPair>& pairs, uint32_t root) {
    TriangleRange range;
    std::vector<uint32_t> stack{root};
    while (!stack.empty()) {
        const BvhPair& pair = pairs.at(stack.back());
        stack.pop_back();
        for (uint32_t child : {pair.child0, pair.child1}) {
            if (child == WF_BVH_NO_CHILD)
                continue;
            const uint32_t count = child & WF_BVH_MAX_LEAF_COUNT;
            const uint32_t index = child >> WF_BVH_COUNT_BITS;
            if (count == 0) {
                stack.push_back(index);
            } else {
                range.first = std::min(range.first, index);
                range.end = std::max(range.end, index + count);
            }
        }
    }
    if (range.first > range.end)
        range = {0, 0};
    return range;
}

VkTransformMatrixKHR identity() {
    VkTransformMatrixKHR m{};
    m.matrix[0][0] = m.matrix[1][1] = m.matrix[2][2] = 1.0f;
    return m;
}

} // namespace

std::unique_ptr<AccelerationStructureSet> buildSceneAcceleration(const Context& context,
                                                                 const PreparedScene& scene,
                                                                 const ShaderVariant& variant) {
    // The triangle table doubles as the vertex buffer: p0, p1, p2 open its 16-byte words.
    Buffer vertices(context, "structure input: triangles",
                    scene.triangles.size() * sizeof(Triangle), kBuildInput);
    if (!scene.triangles.empty())
        vertices.upload(scene.triangles);
    const VkDeviceAddress vertexBase = vertices.address();
    const auto alphaTested = [&](const TriangleRange& range) {
        if (!variant.surface.alphaMask)
            return false;
        for (uint32_t i = range.first; i < range.end; ++i) {
            const uint32_t flags = scene.materials.at(scene.triangles[i].material).flags;
            if (flags & (WF_MATERIAL_ALPHA_MASK | WF_MATERIAL_ALPHA_BLEND))
                return true;
        }
        return false;
    };
    std::vector<BottomLevelInput> bottom;
    std::vector<TopLevelInstance> instances;
    const auto addMesh = [&](const TriangleRange& range) {
        bottom.push_back({vertexBase + VkDeviceAddress(range.first) * sizeof(Triangle),
                          range.end - range.first, true, !alphaTested(range)});
        return static_cast<uint32_t>(bottom.size() - 1);
    };
    if (scene.instances.empty()) {
        if (!scene.triangles.empty()) {
            const uint32_t mesh =
                addMesh({0, static_cast<uint32_t>(scene.triangles.size())});
            instances.push_back({identity(), 0, kTriangleHitGroup, mesh});
        }
    } else {
        std::map<uint32_t, std::pair<uint32_t, TriangleRange>> meshes; // by tree root
        for (const Instance& instance : scene.instances) {
            auto found = meshes.find(instance.blasRoot);
            if (found == meshes.end()) {
                const TriangleRange range = rangeUnder(scene.bvhPairs, instance.blasRoot);
                if (range.first >= (1u << 24))
                    throw UsageError("--traversal rt: a mesh starts past triangle 2^24 of the "
                                     "scene, beyond an instance's custom index; use "
                                     "--traversal bvh");
                found = meshes.emplace(instance.blasRoot, std::make_pair(addMesh(range), range))
                            .first;
            }
            TopLevelInstance placed{};
            for (int column = 0; column < 4; ++column) {
                placed.worldFromObject.matrix[0][column] = instance.worldFromObject0[column];
                placed.worldFromObject.matrix[1][column] = instance.worldFromObject1[column];
                placed.worldFromObject.matrix[2][column] = instance.worldFromObject2[column];
            }
            placed.customIndex = found->second.second.first;
            placed.hitGroup = kTriangleHitGroup;
            placed.bottomLevel = found->second.first;
            instances.push_back(placed);
        }
    }
    Buffer boxes;
    if (variant.sphereLights) {
        const uint32_t spheres = scene.lights.sphereLights;
        std::vector<VkAabbPositionsKHR> positions(spheres);
        for (uint32_t i = 0; i < spheres; ++i) {
            const PunctualLight& light = scene.punctualLights.at(i);
            // A little wider than the sphere, so that rounding in the box test never drops a
            // ray that raySphereNear would hit.
            const float r = light.radius * 1.0001f + 1e-6f * glm::length(light.position);
            positions[i] = {light.position.x - r, light.position.y - r, light.position.z - r,
                            light.position.x + r, light.position.y + r, light.position.z + r};
        }
        boxes = Buffer(context, "structure input: sphere boxes",
                       positions.size() * sizeof(VkAabbPositionsKHR), kBuildInput);
        boxes.upload(positions);
        bottom.push_back({boxes.address(), spheres, false, true});
        instances.push_back(
            {identity(), 0, kSphereHitGroup, static_cast<uint32_t>(bottom.size() - 1)});
    }
    return std::make_unique<AccelerationStructureSet>(context, bottom, instances);
}

} // namespace wf
