// The cameras the viewer switches between (C, 1-9, the overlay's --camera list): the file's,
// in node order, then one framing the whole scene, so that even a file without a camera offers
// a choice and a way back to an overview.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace wf {

struct NamedCamera {
    std::string name;
    Camera camera;
};

struct CameraList {
    std::vector<NamedCamera> cameras;
    uint32_t renderDefault = 0; // the camera `wavefront render` uses: where the viewer starts
};

CameraList viewerCameras(const Scene& scene);

// The camera `nameOrIndex` names (an index into the list, or a camera's name); UsageError
// listing the choices otherwise.
uint32_t findCamera(const CameraList& list, const std::string& nameOrIndex);

// The triangles' bounding sphere (centre of the box, half its diagonal): the orbit target of a
// camera that looks elsewhere, and the scale of fly speed and dolly limits.
struct ViewBounds {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
};
ViewBounds viewBounds(const Scene& scene);

} // namespace wf
