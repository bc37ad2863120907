#include "scene/gltf/gltf_lights_cameras.h"

#include <tiny_gltf.h>

#include <cmath>

#include "scene/gltf/gltf_accessors.h"

namespace wf::gltf {
namespace {

bool finite(const glm::dvec3& v) { return std::isfinite(v.x + v.y + v.z); }

} // namespace

bool cameraFrame(const glm::dmat4& world, CameraKey& key) {
    const glm::dvec3 forward = glm::normalize(-glm::dvec3(world[2]));
    const glm::dvec3 upRaw = glm::dvec3(world[1]);
    const glm::dvec3 up = glm::normalize(upRaw - glm::dot(upRaw, forward) * forward);
    if (!finite(forward) || !finite(up) || !finite(glm::dvec3(world[3])))
        return false;
    key = {glm::vec3(world[3]), glm::vec3(forward), glm::vec3(up)};
    return true;
}

void addNodeCamera(const tinygltf::Model& model, const std::string& file, int nodeIndex,
                   const glm::dmat4& world, Scene& scene) {
    const tinygltf::Node& node = model.nodes[nodeIndex];
    const std::string nodeName = "node " + std::to_string(nodeIndex);
    checkIndex(file, node.camera, model.cameras.size(), "camera", nodeName);
    const tinygltf::Camera& camera = model.cameras[node.camera];
    const std::string name = "camera " + std::to_string(node.camera);
    const bool orthographic = camera.type == "orthographic";
    if (camera.type != "perspective" && !orthographic) {
        warn(file, name + " is skipped: type '" + camera.type +
                       "' is not perspective or orthographic");
        return;
    }
    const double yfov = orthographic ? 0.8 : camera.perspective.yfov;
    const double aspect = orthographic ? camera.orthographic.xmag / camera.orthographic.ymag
                                       : camera.perspective.aspectRatio;
    if (orthographic && !(camera.orthographic.xmag > 0.0 && camera.orthographic.ymag > 0.0 &&
                          camera.orthographic.ymag < 1e30 && std::isfinite(aspect))) {
        warn(file, name + " is skipped: an orthographic camera's xmag and ymag must be "
                          "positive and finite");
        return;
    }
    if (!(yfov > 0.0 && yfov < M_PI) || !(aspect >= 0.0 && std::isfinite(aspect))) {
        warn(file, name + " is skipped: yfov must lie in (0, pi) and aspectRatio be positive");
        return;
    }
    CameraKey frame;
    if (!cameraFrame(world, frame)) {
        warn(file, name + " on " + nodeName + " is skipped: its transform is degenerate");
        return;
    }
    Camera out;
    out.position = frame.position;
    out.forward = frame.forward;
    out.up = frame.up;
    out.yfov = float(yfov);
    out.aspect = float(aspect);
    out.orthoHalfHeight = orthographic ? float(camera.orthographic.ymag) : 0.0f;
    // A thin lens from extras (glTF has none of its own); a bad value is ignored with a warning.
    for (const char* key : {"aperture", "focusDistance"}) {
        if (!camera.extras.IsObject() || !camera.extras.Has(key))
            continue;
        const tinygltf::Value& v = camera.extras.Get(key);
        const double value = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
        if (!(value >= 0.0 && value < 1e30)) {
            warn(file, name + ": extras." + key + " must be a finite number >= 0; ignored");
            continue;
        }
        (std::string(key) == "aperture" ? out.aperture : out.focusDistance) = float(value);
    }
    scene.cameras.push_back(out);
    scene.cameraNames.push_back(!camera.name.empty() ? camera.name
                                : !node.name.empty() ? node.name
                                                     : name);
    if (!scene.hasCamera) {
        scene.camera = out;
        scene.hasCamera = true;
    }
}

void addNodeLight(const tinygltf::Model& model, const std::string& file, int nodeIndex,
                  const glm::dmat4& world, Scene& scene) {
    const tinygltf::Node& node = model.nodes[nodeIndex];
    auto ext = node.extensions.find("KHR_lights_punctual");
    if (ext == node.extensions.end()) {
        return;
    }
    const std::string nodeName = "node " + std::to_string(nodeIndex);
    const tinygltf::Value& ref = ext->second;
    const tinygltf::Value& index = ref.IsObject() && ref.Has("light") ? ref.Get("light")
                                                                       : tinygltf::Value();
    const double lightIndex = index.IsNumber() ? index.GetNumberAsDouble() : -1.0;
    if (!(lightIndex >= 0.0 && lightIndex < double(model.lights.size())) ||
        lightIndex != std::floor(lightIndex)) {
        fail(file, nodeName + " refers to a KHR_lights_punctual light that does not exist (the "
                   "file has " + std::to_string(model.lights.size()) + ")");
    }
    const tinygltf::Light& light = model.lights[size_t(lightIndex)];
    const std::string name = "light " + std::to_string(size_t(lightIndex));
    auto skip = [&](const std::string& why) { warn(file, name + " is skipped: " + why); };

    PunctualLight out{};
    std::vector<double> color = light.color.empty() ? std::vector<double>{1, 1, 1} : light.color;
    if (color.size() != 3) {
        return skip("color needs 3 numbers");
    }
    for (int c = 0; c < 3; ++c) {
        const double value = color[c] * light.intensity;
        if (!(color[c] >= 0.0 && light.intensity >= 0.0 && std::isfinite(value) &&
              value < 1e30)) {
            return skip("color and intensity must be finite and >= 0");
        }
        out.intensity[c] = float(value);
    }
    if (out.intensity.x + out.intensity.y + out.intensity.z == 0.0f) {
        return skip("it emits nothing (zero intensity or colour)");
    }
    const glm::dvec3 position(world[3]);
    const glm::dvec3 direction = glm::normalize(-glm::dvec3(world[2]));
    if (!finite(position) || !finite(direction)) {
        return skip("the transform of " + nodeName + " is degenerate");
    }
    out.position = glm::vec3(position);
    out.direction = glm::vec3(direction);
    out.emitter = WF_NO_EMITTER;
    if (light.type == "point") {
        out.type = WF_LIGHT_POINT;
        if (light.extras.IsObject() && light.extras.Has("radius")) {
            const tinygltf::Value& r = light.extras.Get("radius");
            const double radius = r.IsNumber() ? r.GetNumberAsDouble() : -1.0;
            if (!(radius >= 0.0 && radius < 1e30)) {
                return skip("extras.radius must be a finite number >= 0");
            }
            if (radius > 0.0) {
                out.type = WF_LIGHT_SPHERE;
                out.radius = float(radius);
            }
        }
    } else if (light.type == "spot") {
        const double inner = light.spot.innerConeAngle, outer = light.spot.outerConeAngle;
        if (!(inner >= 0.0 && inner < outer && outer <= M_PI / 2)) {
            return skip("spot cone angles need 0 <= inner < outer <= pi/2");
        }
        out.type = WF_LIGHT_SPOT;
        out.cosInner = float(std::cos(inner));
        out.cosOuter = float(std::cos(outer));
    } else if (light.type == "directional") {
        out.type = WF_LIGHT_DIRECTIONAL;
    } else {
        return skip("type '" + light.type + "' is not point, spot or directional");
    }
    scene.lights.push_back(out);
}

} // namespace wf::gltf
