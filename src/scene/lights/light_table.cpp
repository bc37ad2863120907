#include "scene/lights/light_table.h"

#include "scene/lights/emission_mean.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace wf {

std::vector<Emitter> buildAliasTable(const std::vector<double>& weights) {
    const size_t n = weights.size();
    std::vector<Emitter> table(n);
    double total = 0.0;
    for (double w : weights)
        total += w;
    if (n == 0 || !(total > 0.0))
        return {};
    // Vose's method: split slots into those under and over the mean, and let each small slot
    // borrow the rest of its mass from a large one.
    std::vector<double> scaled(n);
    std::vector<size_t> small, large;
    for (size_t i = 0; i < n; ++i) {
        table[i].pmf = static_cast<float>(weights[i] / total);
        scaled[i] = weights[i] / total * static_cast<double>(n);
        (scaled[i] < 1.0 ? small : large).push_back(i);
    }
    while (!small.empty() && !large.empty()) {
        size_t s = small.back(), l = large.back();
        small.pop_back();
        table[s].aliasProb = static_cast<float>(scaled[s]);
        table[s].alias = static_cast<uint32_t>(l);
        scaled[l] -= 1.0 - scaled[s];
        if (scaled[l] < 1.0) {
            large.pop_back();
            small.push_back(l);
        }
    }
    // Whatever remains is 1 up to rounding: keep the slot itself.
    for (size_t i : small) {
        table[i].aliasProb = 1.0f;
        table[i].alias = static_cast<uint32_t>(i);
    }
    for (size_t i : large) {
        table[i].aliasProb = 1.0f;
        table[i].alias = static_cast<uint32_t>(i);
    }
    return table;
}

namespace {

double mean(glm::vec3 v) { return (double(v.x) + v.y + v.z) / 3.0; }

double lightPower(const PunctualLight& light, const SceneBounds& bounds) {
    switch (light.type) {
    case WF_LIGHT_SPOT:
        return 2.0 * M_PI * (1.0 - 0.5 * (light.cosInner + light.cosOuter)) * mean(light.intensity);
    case WF_LIGHT_DIRECTIONAL:
        return M_PI * double(bounds.radius) * bounds.radius * mean(light.intensity);
    default: // point and sphere lights of the same intensity carry the same power
        return 4.0 * M_PI * mean(light.intensity);
    }
}

} // namespace

SceneBounds sceneBounds(Bounds box, const std::vector<PunctualLight>& lights) {
    for (const PunctualLight& light : lights)
        if (light.type != WF_LIGHT_DIRECTIONAL) {
            const float r = light.type == WF_LIGHT_SPHERE ? light.radius : 0.0f;
            box.grow(light.position - glm::vec3(r));
            box.grow(light.position + glm::vec3(r));
        }
    SceneBounds bounds;
    if (box.empty())
        return bounds;
    bounds.center = 0.5f * (box.lo + box.hi);
    bounds.radius = std::max(0.5f * glm::length(box.hi - box.lo), 1e-6f);
    return bounds;
}

SceneBounds sceneBounds(const std::vector<Triangle>& triangles,
                        const std::vector<PunctualLight>& lights) {
    Bounds box;
    for (const Triangle& tri : triangles)
        for (const glm::vec3& p : {tri.p0, tri.p1, tri.p2})
            box.grow(p);
    return sceneBounds(box, lights);
}

SceneBounds sceneBounds(const Scene& scene) { return sceneBounds(triangleBounds(scene), scene.lights); }

LightTable buildLightTable(std::vector<Triangle>& triangles, const std::vector<Material>& materials,
                           std::vector<PunctualLight>& lights, const Environment& environment,
                           const SceneBounds& bounds, const SurfaceData& surface) {
    std::vector<double> powers;
    std::vector<uint32_t> sources;
    LightTable table;
    for (uint32_t i = 0; i < triangles.size(); ++i) {
        Triangle& tri = triangles[i];
        tri.emitter = WF_NO_EMITTER;
        const Material& material = materials[tri.material];
        double area = 0.5 * glm::length(glm::cross(glm::dvec3(tri.p1) - glm::dvec3(tri.p0),
                                                   glm::dvec3(tri.p2) - glm::dvec3(tri.p0)));
        double sides = (material.flags & WF_MATERIAL_DOUBLE_SIDED) ? 2.0 : 1.0;
        glm::vec3 emission = material.emission;
        if (material.emissiveTexture != WF_NO_TEXTURE && emission != glm::vec3(0.0f))
            emission *= meanEmissiveTexture(surface, material.emissiveTexture, i);
        double power = mean(emission) * area * M_PI * sides;
        if (!(power > 0.0) || !std::isfinite(power))
            continue; // zero-area or non-emitting: never sampled, still hit by BSDF rays
        tri.emitter = static_cast<uint32_t>(sources.size());
        sources.push_back(WF_EMITTER_TRIANGLE | i);
        powers.push_back(power);
        ++table.triangleEmitters;
    }

    std::stable_partition(lights.begin(), lights.end(), [](const PunctualLight& light) {
        return light.type == WF_LIGHT_SPHERE;
    });
    for (uint32_t i = 0; i < lights.size(); ++i) {
        PunctualLight& light = lights[i];
        light.emitter = WF_NO_EMITTER;
        if (light.type == WF_LIGHT_SPHERE)
            ++table.sphereLights;
        double power = lightPower(light, bounds);
        if (!(power > 0.0) || !std::isfinite(power))
            continue;
        light.emitter = static_cast<uint32_t>(sources.size());
        sources.push_back(WF_EMITTER_LIGHT | i);
        powers.push_back(power);
        if (light.type != WF_LIGHT_SPHERE)
            ++table.deltaLights;
    }

    if (environment.present()) {
        std::vector<double> texelWeights(size_t(environment.width) * environment.height);
        double radianceSum = 0.0, solidAngleSum = 0.0;
        for (uint32_t y = 0; y < environment.height; ++y) {
            double sinTheta = std::sin(M_PI * (y + 0.5) / environment.height);
            for (uint32_t x = 0; x < environment.width; ++x) {
                size_t i = size_t(y) * environment.width + x;
                const float* rgb = &environment.rgb[3 * i];
                double luminance = (double(rgb[0]) + rgb[1] + rgb[2]) / 3.0;
                texelWeights[i] = luminance * sinTheta;
                radianceSum += luminance * sinTheta;
                solidAngleSum += sinTheta;
            }
        }
        table.environmentTexels = buildAliasTable(texelWeights);
        // Power the environment sends into the scene's bounding sphere: mean radiance over
        // the sphere of directions, times 4 pi sr, times the disc it crosses.
        double power = radianceSum / solidAngleSum * 4.0 * M_PI * M_PI * double(bounds.radius) *
                       bounds.radius;
        if (power > 0.0 && std::isfinite(power) && !table.environmentTexels.empty()) {
            table.environmentEmitter = static_cast<uint32_t>(sources.size());
            sources.push_back(WF_EMITTER_ENVIRONMENT);
            powers.push_back(power);
        }
    }

    table.emitters = buildAliasTable(powers);
    for (size_t k = 0; k < table.emitters.size(); ++k) {
        table.emitters[k].source = sources[k];
        table.totalPower += powers[k];
    }
    return table;
}

} // namespace wf
