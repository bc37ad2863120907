#include "scene/gltf/gltf_scene_limits.h"

#include <unistd.h>

#include <tiny_gltf.h>

#include <algorithm>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/gltf_instancing.h"

namespace wf::gltf {

namespace {

std::size_t physicalMemoryBytes() {
    const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? std::size_t(pages) * std::size_t(pageSize) : 0;
}

std::size_t memoryTriangleLimit() {
    const std::size_t bytes = physicalMemoryBytes();
    return bytes > 0 ? bytes / kHostBytesPerTriangle : kTraversalTriangleLimit;
}

} // namespace

std::size_t maxSceneTriangles() {
    return std::min(kTraversalTriangleLimit, memoryTriangleLimit());
}

std::size_t trianglesOfPrimitive(int mode, std::size_t corners) {
    if (mode == TINYGLTF_MODE_TRIANGLES)
        return corners / 3;
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN)
        return corners >= 3 ? corners - 2 : 0;
    return 0;
}

std::string sceneTriangleLimitReason() {
    if (memoryTriangleLimit() >= kTraversalTriangleLimit)
        return "the BVH's triangle index limit";
    return "the most this machine's " + std::to_string(physicalMemoryBytes() >> 30) +
           " GiB of memory holds at about " + std::to_string(kHostBytesPerTriangle) +
           " bytes a triangle (meshes placed by several nodes are copied)";
}

std::size_t checkPlacedTriangles(const tinygltf::Model& model, const std::string& file,
                                 const std::vector<std::size_t>& placements,
                                 const std::vector<bool>& instanced) {
    double total = 0.0, instances = 0.0;
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        double triangles = 0.0;
        for (const tinygltf::Primitive& primitive : model.meshes[m].primitives)
            triangles += double(estimatedTriangles(model, primitive));
        total += triangles * (instanced[m] ? std::min<double>(placements[m], 1.0)
                                           : double(placements[m]));
        instances += instanced[m] ? double(placements[m]) : 0.0;
    }
    if (total > double(maxSceneTriangles()))
        fail(file, "its nodes place more than " + std::to_string(maxSceneTriangles()) +
                       " triangles, " + sceneTriangleLimitReason());
    if (instances > double(kMaxInstances))
        fail(file, "its nodes place more than " + std::to_string(kMaxInstances) +
                       " instances, the most the renderer keeps");
    return std::size_t(total);
}

} // namespace wf::gltf
