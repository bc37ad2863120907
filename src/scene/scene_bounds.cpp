// World-space extents of a scene whose meshes may be instanced (scene.h).
#include "scene/scene.h"

namespace wf {

uint64_t Scene::instancedTriangleCount() const {
    uint64_t count = worldTriangleCount();
    for (const MeshPlacement& placement : placements)
        count += meshes[placement.mesh].triangleCount;
    return count;
}

Bounds transformedBounds(const Bounds& box, const glm::mat4& worldFromObject) {
    Bounds out;
    if (box.empty())
        return out;
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                          (corner & 4) ? box.hi.z : box.lo.z);
        out.grow(glm::vec3(worldFromObject * glm::vec4(p, 1.0f)));
    }
    return out;
}

Bounds triangleBounds(const Scene& scene) {
    Bounds bounds;
    const size_t world = scene.worldTriangleCount();
    for (size_t i = 0; i < world; ++i)
        for (const glm::vec3& p : {scene.triangles[i].p0, scene.triangles[i].p1,
                                   scene.triangles[i].p2})
            bounds.grow(p);
    std::vector<Bounds> meshBoxes(scene.meshes.size());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
        const MeshRange& range = scene.meshes[m];
        for (uint32_t i = range.firstTriangle; i < range.firstTriangle + range.triangleCount; ++i)
            for (const glm::vec3& p : {scene.triangles[i].p0, scene.triangles[i].p1,
                                       scene.triangles[i].p2})
                meshBoxes[m].grow(p);
    }
    for (const MeshPlacement& placement : scene.placements) {
        const Bounds box = transformedBounds(meshBoxes[placement.mesh], placement.worldFromObject);
        if (!box.empty()) {
            bounds.grow(box.lo);
            bounds.grow(box.hi);
        }
    }
    return bounds;
}

} // namespace wf
