// Counts and bounds in one pass over the triangles; cheap next to loading, so always run.
#include "scene/scene_summary.h"

#include <cstdio>

namespace wf {
namespace {

bool isEmissive(const Material& material) {
    return material.emission.x > 0.0f || material.emission.y > 0.0f ||
           material.emission.z > 0.0f;
}

std::string formatVec(const glm::vec3& v) {
    char text[96];
    std::snprintf(text, sizeof(text), "(%.4g, %.4g, %.4g)", double(v.x), double(v.y),
                  double(v.z));
    return text;
}

} // namespace

SceneSummary summarize(const Scene& scene) {
    SceneSummary summary;
    summary.triangleCount = scene.triangles.size();
    summary.materialCount = scene.materials.size();
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& t = scene.triangles[i];
        // Out-of-range material indices are the loader's to reject; here they just count as
        // not emissive rather than reading past the array.
        if (t.material < scene.materials.size() && isEmissive(scene.materials[t.material])) {
            ++summary.emissiveTriangleCount;
        }
        glm::vec3 lo = glm::min(glm::min(t.p0, t.p1), t.p2);
        glm::vec3 hi = glm::max(glm::max(t.p0, t.p1), t.p2);
        summary.boundsLo = i == 0 ? lo : glm::min(summary.boundsLo, lo);
        summary.boundsHi = i == 0 ? hi : glm::max(summary.boundsHi, hi);
    }
    summary.hasEmitters = summary.emissiveTriangleCount > 0;
    return summary;
}

std::string describe(const SceneSummary& summary) {
    std::string text = std::to_string(summary.triangleCount) + " triangles, " +
                       std::to_string(summary.materialCount) + " materials, " +
                       std::to_string(summary.emissiveTriangleCount) + " emissive triangles";
    if (summary.triangleCount > 0) {
        text += "; bounds " + formatVec(summary.boundsLo) + " to " + formatVec(summary.boundsHi);
    }
    text += ".";
    if (summary.triangleCount == 0) {
        text += " The scene has no triangles: the image will be black.";
    } else if (!summary.hasEmitters) {
        text += " No material emits light (emissiveFactor is zero everywhere): the image will"
                " be black.";
    }
    return text;
}

} // namespace wf
