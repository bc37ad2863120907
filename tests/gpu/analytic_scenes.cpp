#include "analytic_scenes.h"

#include <cmath>

namespace wf::test {

Scene floorScene(float albedo) {
    Scene scene;
    Material material{};
    material.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    material.roughness = 1.0f;
    material.ior = 1.5f;
    material.specular = 0.0f; // exact Lambert
    material.specularColor = glm::vec3(1.0f);
    scene.materials.push_back(material);
    const float s = 100.0f;
    const glm::vec3 a(-s, 0, -s), b(-s, 0, s), c(s, 0, s), d(s, 0, -s);
    scene.triangles.push_back({a, 0, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, 0, c, WF_NO_EMITTER, d, 0});
    scene.camera.position = glm::vec3(0.0f, 2.0f, 2.0f);
    scene.camera.forward = glm::normalize(-scene.camera.position);
    scene.camera.up = glm::normalize(glm::cross(glm::cross(scene.camera.forward,
                                                           glm::vec3(0, 1, 0)),
                                                scene.camera.forward));
    scene.camera.yfov = 5e-4f;
    scene.hasCamera = true;
    return scene;
}

PunctualLight sphereLight(glm::vec3 center, float radius, glm::vec3 intensity) {
    PunctualLight light{};
    light.type = WF_LIGHT_SPHERE;
    light.position = center;
    light.radius = radius;
    light.intensity = intensity;
    return light;
}

PunctualLight pointLight(glm::vec3 position, glm::vec3 intensity) {
    PunctualLight light{};
    light.type = WF_LIGHT_POINT;
    light.position = position;
    light.intensity = intensity;
    return light;
}

PunctualLight directionalLight(glm::vec3 direction, glm::vec3 illuminance) {
    PunctualLight light{};
    light.type = WF_LIGHT_DIRECTIONAL;
    light.direction = glm::normalize(direction);
    light.intensity = illuminance;
    return light;
}

Environment rowEnvironment(uint32_t width, uint32_t height, float (*rowRadiance)(uint32_t)) {
    Environment env;
    env.width = width;
    env.height = height;
    env.rgb.resize(size_t(width) * height * 3);
    for (uint32_t y = 0; y < height; ++y)
        for (uint32_t x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c)
                env.rgb[(size_t(y) * width + x) * 3 + c] = rowRadiance ? rowRadiance(y) : 0.0f;
    return env;
}

double rowEnvironmentIrradiance(uint32_t height, float (*rowRadiance)(uint32_t)) {
    // Row r spans theta in [r, r + 1] * pi / height; cos-weighted solid angle of the band
    // above the horizon: 2 pi * (sin^2 theta1 - sin^2 theta0) / 2.
    double irradiance = 0.0;
    for (uint32_t r = 0; r < height; ++r) {
        double theta0 = M_PI * r / height, theta1 = std::min(M_PI * (r + 1) / height, M_PI / 2);
        if (theta0 >= M_PI / 2)
            break;
        double s0 = std::sin(theta0), s1 = std::sin(theta1);
        irradiance += rowRadiance(r) * M_PI * (s1 * s1 - s0 * s0);
    }
    return irradiance;
}

double addDiracLights(Scene& scene) {
    scene.lights.push_back(pointLight({0.3f, 2.0f, -0.4f}, glm::vec3(5.0f)));
    scene.lights.push_back(directionalLight({0.2f, -1.0f, 0.1f}, glm::vec3(2.0f)));
    // A spot aimed at the origin (inside its inner cone: full intensity), and one aimed away
    // (outside its outer cone: no light).
    const glm::vec3 spotPosition(-0.2f, 1.5f, 0.1f);
    PunctualLight spot = pointLight(spotPosition, glm::vec3(3.0f));
    spot.type = WF_LIGHT_SPOT;
    spot.direction = glm::normalize(-spotPosition);
    spot.cosInner = std::cos(0.3f);
    spot.cosOuter = std::cos(0.5f);
    scene.lights.push_back(spot);
    spot.direction = glm::normalize(glm::vec3(1.0f, -0.2f, 0.0f));
    scene.lights.push_back(spot);
    const double spotIrradiance = 3.0 * spotPosition.y / std::pow(glm::length(spotPosition), 3.0);
    const glm::vec3 toPoint(0.3f, 2.0f, -0.4f);
    const double pointIrradiance = 5.0 * toPoint.y / std::pow(glm::length(toPoint), 3.0);
    const double directionalIrradiance = 2.0 * glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f)).y * -1.0;
    return pointIrradiance + directionalIrradiance + spotIrradiance;
}

Scene furnaceSphere(const Material& material, float environmentRadiance) {
    Scene scene;
    scene.materials.push_back(material);
    const int rings = 48, segments = 96;
    auto point = [&](int i, int j) {
        double theta = M_PI * i / rings, phi = 2.0 * M_PI * j / segments;
        return glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
    };
    for (int i = 0; i < rings; ++i)
        for (int j = 0; j < segments; ++j) {
            glm::vec3 a = point(i, j), b = point(i + 1, j), c = point(i + 1, j + 1),
                      d = point(i, j + 1);
            if (i > 0)
                scene.triangles.push_back({a, 0, d, WF_NO_EMITTER, b, 0});
            if (i < rings - 1)
                scene.triangles.push_back({b, 0, d, WF_NO_EMITTER, c, 0});
        }
    scene.environment = rowEnvironment(1, 1, nullptr);
    scene.environment.rgb = {environmentRadiance, environmentRadiance, environmentRadiance};
    scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    scene.camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.camera.yfov = 0.25f; // the sphere fills the view
    scene.hasCamera = true;
    return scene;
}

} // namespace wf::test
