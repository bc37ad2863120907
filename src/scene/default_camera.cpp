#include "scene/default_camera.h"

#include <cmath>
#include <limits>

namespace wf {

Camera frameBounds(const Scene& scene) {
    glm::vec3 lo(std::numeric_limits<float>::max());
    glm::vec3 hi(-std::numeric_limits<float>::max());
    for (const Triangle& tri : scene.triangles)
        for (const glm::vec3& p : {tri.p0, tri.p1, tri.p2}) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    Camera camera;
    if (scene.triangles.empty())
        return camera;
    glm::vec3 center = 0.5f * (lo + hi);
    float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    camera.position = center + glm::vec3(0.0f, 0.0f, radius / std::sin(0.5f * camera.yfov));
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return camera;
}

} // namespace wf
