#include "light_rig.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "analytic_scenes.h"
#include "direct_lighting.h"

namespace wf::test {
namespace {

Material lambert(float albedo, float emission) {
    Material material{};
    material.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    material.emission = glm::vec3(emission);
    material.roughness = 1.0f;
    material.ior = 1.5f;
    material.specular = 0.0f; // KHR_materials_specular 0: exact Lambert
    material.specularColor = glm::vec3(1.0f);
    return material;
}

void addQuad(Scene& scene, const RigQuad& quad, uint32_t material) {
    const glm::vec3 a = quad.corner, b = a + quad.edgeU, c = b + quad.edgeV, d = a + quad.edgeV;
    scene.triangles.push_back({a, material, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, material, c, WF_NO_EMITTER, d, 0});
}

constexpr double kNoHit = std::numeric_limits<double>::infinity();

double hitQuad(const RigQuad& quad, glm::dvec3 o, glm::dvec3 d) {
    const glm::dvec3 u(quad.edgeU), v(quad.edgeV), normal = glm::cross(u, v);
    const double denominator = glm::dot(normal, d);
    if (denominator == 0.0)
        return kNoHit;
    const double t = glm::dot(normal, glm::dvec3(quad.corner) - o) / denominator;
    if (!(t > 0.0))
        return kNoHit;
    const glm::dvec3 q = o + t * d - glm::dvec3(quad.corner);
    // Coordinates in the (u, v) frame; the quads are parallelograms.
    const double uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v);
    const double qu = glm::dot(q, u), qv = glm::dot(q, v), det = uu * vv - uv * uv;
    const double s = (vv * qu - uv * qv) / det, r = (uu * qv - uv * qu) / det;
    return s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0 ? t : kNoHit;
}

double hitSphere(const PunctualLight& light, glm::dvec3 o, glm::dvec3 d) {
    const glm::dvec3 oc = o - glm::dvec3(light.position);
    const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - double(light.radius) * light.radius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0)
        return kNoHit;
    const double t0 = -b - std::sqrt(discriminant), t1 = -b + std::sqrt(discriminant);
    return t0 > 0.0 ? t0 : (t1 > 0.0 ? t1 : kNoHit);
}

// Irradiance at p from the rig's lights; with `unitRadiance`, from its area lights and sky at
// radiance 1 (their projected solid angle).
double irradiance(const LightRig& rig, glm::dvec3 p, glm::dvec3 n, bool unitRadiance = false) {
    double e = 0.0;
    for (const RigQuad& quad : rig.emitters) {
        const glm::dvec3 a(quad.corner), u(quad.edgeU), v(quad.edgeV);
        const glm::dvec3 corners[4] = {a, a + u, a + u + v, a + v};
        e += polygonIrradiance(p, n, corners, 4, unitRadiance ? 1.0 : quad.value);
    }
    if (unitRadiance) {
        for (const PunctualLight& light : rig.lights)
            if (light.type == WF_LIGHT_SPHERE)
                e += sphereIrradiance(p, n, glm::dvec3(light.position), light.radius, 1.0);
        return rig.skyRow ? M_PI : e;
    }
    for (const PunctualLight& light : rig.lights) {
        const glm::dvec3 position(light.position), direction(light.direction);
        const double intensity = light.intensity.x;
        switch (light.type) {
        case WF_LIGHT_SPHERE:
            e += sphereIrradiance(p, n, position, light.radius,
                                  intensity / (M_PI * light.radius * light.radius));
            break;
        case WF_LIGHT_POINT:
            e += pointIrradiance(p, n, position, intensity);
            break;
        case WF_LIGHT_SPOT:
            e += spotIrradiance(p, n, position, direction, light.cosInner, light.cosOuter,
                                intensity);
            break;
        default:
            e += directionalIrradiance(n, direction, intensity);
        }
    }
    if (rig.skyRow) // an unbounded floor facing +y sees the whole upper hemisphere
        e += n.y > 0.999999 ? rowEnvironmentIrradiance(8, rig.skyRow) : std::nan("");
    return e;
}

} // namespace

Camera lookAt(glm::vec3 eye, glm::vec3 target, float yfov) {
    Camera camera;
    camera.position = eye;
    camera.forward = glm::normalize(target - eye);
    camera.up = glm::normalize(
        glm::cross(glm::cross(camera.forward, glm::vec3(0, 1, 0)), camera.forward));
    camera.yfov = yfov;
    return camera;
}

Scene rigScene(const LightRig& rig) {
    Scene scene;
    for (const RigQuad& quad : rig.receivers) {
        scene.materials.push_back(lambert(quad.value, 0.0f));
        addQuad(scene, quad, uint32_t(scene.materials.size() - 1));
    }
    for (const RigQuad& quad : rig.emitters) {
        scene.materials.push_back(lambert(0.0f, quad.value));
        addQuad(scene, quad, uint32_t(scene.materials.size() - 1));
    }
    scene.lights = rig.lights;
    if (rig.skyRow)
        scene.environment = rowEnvironment(8, 8, rig.skyRow);
    scene.camera = rig.camera;
    scene.hasCamera = true;
    return scene;
}

ExpectedImage expectedDirectLight(const LightRig& rig, uint32_t width, uint32_t height) {
    const size_t pixels = size_t(width) * height;
    ExpectedImage image{std::vector<double>(pixels, 0.0), std::vector<bool>(pixels, true),
                        std::vector<double>(pixels, 0.0)};
    const Camera& camera = rig.camera;
    const glm::dvec3 forward(camera.forward), up(camera.up);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, up));
    const double tanHalf = std::tan(0.5 * camera.yfov), aspect = double(width) / height;
    const int positions = 16;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x) {
            const size_t pixel = size_t(y) * width + x;
            const RigQuad* firstReceiver = nullptr;
            for (int j = 0; j < positions * positions && image.valid[pixel]; ++j) {
                const double nx = ((x + (j % positions + 0.5) / positions) / width) * 2.0 - 1.0;
                const double ny = ((y + (j / positions + 0.5) / positions) / height) * 2.0 - 1.0;
                const glm::dvec3 d = glm::normalize(forward + right * (nx * tanHalf * aspect) -
                                                    up * (ny * tanHalf));
                const glm::dvec3 o(camera.position);
                double nearest = kNoHit;
                const RigQuad* receiver = nullptr;
                for (const RigQuad& quad : rig.receivers) {
                    const double t = hitQuad(quad, o, d);
                    if (t < nearest) {
                        nearest = t;
                        receiver = &quad;
                    }
                }
                for (const RigQuad& quad : rig.emitters)
                    if (hitQuad(quad, o, d) < nearest)
                        receiver = nullptr;
                for (const PunctualLight& light : rig.lights)
                    if (light.type == WF_LIGHT_SPHERE && hitSphere(light, o, d) < nearest)
                        receiver = nullptr;
                // A pixel across two receivers is left out too: the positions estimate how
                // much of it each covers only to 1 / positions.
                if (!receiver || (j > 0 && receiver != firstReceiver)) {
                    image.valid[pixel] = false;
                    break;
                }
                firstReceiver = receiver;
                glm::dvec3 n = glm::normalize(glm::cross(glm::dvec3(receiver->edgeU),
                                                         glm::dvec3(receiver->edgeV)));
                if (glm::dot(n, d) > 0.0)
                    n = -n; // receivers shade two-sided: the side the camera sees
                const glm::dvec3 p = o + nearest * d;
                const double share = 1.0 / (positions * positions);
                image.value[pixel] += receiver->value / M_PI * irradiance(rig, p, n) * share;
                image.hitProbability[pixel] += irradiance(rig, p, n, true) / M_PI * share;
            }
        }
    // A sample between the positions may see the light at a pixel next to one that does.
    std::vector<bool> seen = image.valid;
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            for (uint32_t ny = y > 0 ? y - 1 : 0; ny <= std::min(y + 1, height - 1); ++ny)
                for (uint32_t nx = x > 0 ? x - 1 : 0; nx <= std::min(x + 1, width - 1); ++nx)
                    if (!seen[size_t(ny) * width + nx])
                        image.valid[size_t(y) * width + x] = false;
    for (size_t i = 0; i < pixels; ++i)
        if (!image.valid[i])
            image.value[i] = image.hitProbability[i] = 0.0;
    return image;
}

} // namespace wf::test
