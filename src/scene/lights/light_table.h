// The light table for next-event estimation: every light of the scene (emissive triangles of
// positive area, KHR_lights_punctual and sphere lights, the environment) in one Walker alias
// table, chosen with probability proportional to an estimate of its power (O(1) per sample).
// Run after the BVH builder has reordered the triangles.
#pragma once
#include <vector>

#include "scene/scene.h"

namespace wf {

struct LightTable {
    std::vector<Emitter> emitters;
    // Alias table over the environment's texels, weighted by luminance x sin(theta), so that
    // directions are drawn in proportion to the light they bring.
    std::vector<Emitter> environmentTexels;
    uint32_t environmentEmitter = WF_NO_EMITTER;
    uint32_t triangleEmitters = 0;
    uint32_t sphereLights = 0; // lights[0, sphereLights) are spheres, the rest Dirac lights
    uint32_t deltaLights = 0;
    double totalPower = 0.0;
};

struct SceneBounds {
    glm::vec3 center{0.0f};
    float radius = 0.0f; // bounding-sphere radius of the triangles and the finite lights
};

SceneBounds sceneBounds(const std::vector<Triangle>& triangles,
                        const std::vector<PunctualLight>& lights);
// `box` (world-space triangles) grown by the finite lights.
SceneBounds sceneBounds(Bounds box, const std::vector<PunctualLight>& lights);
// Every world-space triangle, instance and finite light of a loaded scene.
SceneBounds sceneBounds(const Scene& scene);

// Fills in each triangle's `emitter` field (WF_NO_EMITTER for non-emitters), sorts `lights` so
// that sphere lights come first, and sets each light's `emitter`.
// A triangle with an emissive texture weighs by the texture's mean over it (`surface`, in
// triangle order; meanEmissiveTexture).
LightTable buildLightTable(std::vector<Triangle>& triangles, const std::vector<Material>& materials,
                           std::vector<PunctualLight>& lights, const Environment& environment,
                           const SceneBounds& bounds, const SurfaceData& surface = SurfaceData{});

// Walker/Vose alias table over non-negative weights with a positive sum: pmf, threshold and
// alias per slot (Emitter.source is left for the caller).
std::vector<Emitter> buildAliasTable(const std::vector<double>& weights);

} // namespace wf
