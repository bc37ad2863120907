#include "scene/default_camera.h"

#include <cmath>
#include <limits>

#include "errors.h"

namespace wf {

Camera frameBounds(const Scene& scene) {
    const Bounds box = triangleBounds(scene);
    const glm::vec3 lo = box.lo, hi = box.hi;
    Camera camera;
    if (box.empty())
        return camera;
    glm::vec3 center = 0.5f * (lo + hi);
    float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    camera.position = center + glm::vec3(0.0f, 0.0f, radius / std::sin(0.5f * camera.yfov));
    camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    return camera;
}

Camera selectCamera(const Scene& scene, const std::string& nameOrIndex, const std::string& file) {
    for (size_t i = 0; i < scene.cameraNames.size() && i < scene.cameras.size(); ++i)
        if (scene.cameraNames[i] == nameOrIndex)
            return scene.cameras[i];
    const bool digits = !nameOrIndex.empty() && nameOrIndex.size() < 10 &&
                        nameOrIndex.find_first_not_of("0123456789") == std::string::npos;
    if (digits && std::stoul(nameOrIndex) < scene.cameras.size())
        return scene.cameras[std::stoul(nameOrIndex)];
    std::string known;
    for (size_t i = 0; i < scene.cameraNames.size(); ++i)
        known += (i ? ", " : "") + std::to_string(i) + " '" + scene.cameraNames[i] + "'";
    throw InputError(file + ": no camera '" + nameOrIndex + "'; " +
                     (known.empty() ? std::string("the file has no usable camera")
                                    : "the file has " + known));
}

} // namespace wf
