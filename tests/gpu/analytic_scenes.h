// Scenes with closed-form answers, built in code: a Lambertian floor under a light whose
// irradiance at the point the camera looks at is known exactly.
#pragma once
#include "scene/scene.h"

namespace wf::test {

// A 200 x 200 horizontal quad at y = 0 (facing +y) with Lambert albedo `albedo`
// (KHR_materials_specular 0), and a narrow camera looking at the origin from above at an angle,
// so every pixel sees a point within ~1e-3 of the origin.
Scene floorScene(float albedo);

// Radiance leaving the floor at the origin towards the camera: albedo / pi x irradiance.
inline double lambertRadiance(double albedo, double irradiance) {
    return albedo / 3.14159265358979323846 * irradiance;
}

PunctualLight sphereLight(glm::vec3 center, float radius, glm::vec3 intensity);
PunctualLight pointLight(glm::vec3 position, glm::vec3 intensity);
PunctualLight directionalLight(glm::vec3 direction, glm::vec3 illuminance);

// Adds a point light, a directional light, a spot aimed at the origin and one aimed away from
// it; returns their irradiance at the origin on an upward-facing surface (floorScene's).
double addDiracLights(Scene& scene);

// An equirectangular environment of width x height texels whose row r has radiance
// rowRadiance(r) (grey).
Environment rowEnvironment(uint32_t width, uint32_t height, float (*rowRadiance)(uint32_t));

// Irradiance at an upward-facing point from that environment: rows above the horizon only.
double rowEnvironmentIrradiance(uint32_t height, float (*rowRadiance)(uint32_t));

// A closed UV sphere (outward, counter-clockwise) of `material` at the origin, radius 1, seen by
// a camera whose view is filled by it, with no light but a uniform environment of radiance
// `environmentRadiance`: the BSDF white-furnace test.
Scene furnaceSphere(const Material& material, float environmentRadiance);

} // namespace wf::test
