#include "viewer/camera_list.h"

#include <algorithm>
#include <limits>

#include "errors.h"
#include "scene/default_camera.h"

namespace wf {
namespace {

bool sameCamera(const Camera& a, const Camera& b) {
    return a.position == b.position && a.forward == b.forward && a.up == b.up &&
           a.yfov == b.yfov;
}

} // namespace

CameraList viewerCameras(const Scene& scene) {
    CameraList list;
    bool renderCameraListed = false;
    for (size_t i = 0; i < scene.cameras.size(); ++i) {
        std::string name = i < scene.cameraNames.size() && !scene.cameraNames[i].empty()
                               ? scene.cameraNames[i]
                               : "camera " + std::to_string(i);
        if (scene.hasCamera && !renderCameraListed && sameCamera(scene.cameras[i], scene.camera)) {
            list.renderDefault = static_cast<uint32_t>(list.cameras.size());
            renderCameraListed = true;
        }
        list.cameras.push_back({std::move(name), scene.cameras[i]});
    }
    if (scene.hasCamera && !renderCameraListed) {
        list.renderDefault = 0;
        list.cameras.insert(list.cameras.begin(), {"file camera", scene.camera});
    }
    list.cameras.push_back({"framing camera", frameBounds(scene)});
    if (!scene.hasCamera) // `render` frames the scene itself when the file has no camera
        list.renderDefault = static_cast<uint32_t>(list.cameras.size() - 1);
    return list;
}

uint32_t findCamera(const CameraList& list, const std::string& nameOrIndex) {
    const bool digits = !nameOrIndex.empty() &&
                        nameOrIndex.find_first_not_of("0123456789") == std::string::npos;
    if (digits && nameOrIndex.size() < 9 && std::stoul(nameOrIndex) < list.cameras.size())
        return static_cast<uint32_t>(std::stoul(nameOrIndex));
    std::string names;
    for (size_t i = 0; i < list.cameras.size(); ++i) {
        if (list.cameras[i].name == nameOrIndex)
            return static_cast<uint32_t>(i);
        names += (i ? ", " : "") + std::to_string(i) + " '" + list.cameras[i].name + "'";
    }
    throw UsageError("--camera " + nameOrIndex + ": no such camera; the scene offers " + names);
}

ViewBounds viewBounds(const Scene& scene) {
    ViewBounds bounds;
    const Bounds box = triangleBounds(scene);
    if (box.empty())
        return bounds;
    const glm::vec3 lo = box.lo, hi = box.hi;
    bounds.center = 0.5f * (lo + hi);
    bounds.radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    return bounds;
}

} // namespace wf
