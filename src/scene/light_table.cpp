#include "scene/light_table.h"

#include <cmath>

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

LightTable buildLightTable(std::vector<Triangle>& triangles,
                           const std::vector<Material>& materials) {
    std::vector<double> powers;
    std::vector<uint32_t> emissive;
    for (uint32_t i = 0; i < triangles.size(); ++i) {
        Triangle& tri = triangles[i];
        tri.emitter = WF_NO_EMITTER;
        const Material& material = materials[tri.material];
        glm::dvec3 e(material.emission);
        double meanRadiance = (e.x + e.y + e.z) / 3.0;
        double area = 0.5 * glm::length(glm::cross(glm::dvec3(tri.p1) - glm::dvec3(tri.p0),
                                                   glm::dvec3(tri.p2) - glm::dvec3(tri.p0)));
        double sides = (material.flags & WF_MATERIAL_DOUBLE_SIDED) ? 2.0 : 1.0;
        double power = meanRadiance * area * M_PI * sides;
        if (!(power > 0.0) || !std::isfinite(power))
            continue; // zero-area or non-emitting: never sampled, still hit by BSDF rays
        emissive.push_back(i);
        powers.push_back(power);
    }
    LightTable table;
    table.emitters = buildAliasTable(powers);
    for (size_t k = 0; k < table.emitters.size(); ++k) {
        table.emitters[k].triangle = emissive[k];
        triangles[emissive[k]].emitter = static_cast<uint32_t>(k);
        table.totalPower += powers[k];
    }
    return table;
}

} // namespace wf
