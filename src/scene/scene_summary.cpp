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

// "2 point, 1 spot" from (count, name) pairs, skipping zeros; `none` if all are zero.
std::string listCounts(std::initializer_list<std::pair<size_t, const char*>> items,
                       const char* none) {
    std::string text;
    for (const auto& [count, name] : items)
        if (count > 0)
            text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + name;
    return text.empty() ? none : text;
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
    }
    const Bounds box = triangleBounds(scene);
    if (!box.empty()) {
        summary.boundsLo = box.lo;
        summary.boundsHi = box.hi;
    }
    summary.hasEmitters = summary.emissiveTriangleCount > 0;
    for (const PunctualLight& light : scene.lights) {
        summary.pointLights += light.type == WF_LIGHT_POINT;
        summary.spotLights += light.type == WF_LIGHT_SPOT;
        summary.directionalLights += light.type == WF_LIGHT_DIRECTIONAL;
        summary.sphereLights += light.type == WF_LIGHT_SPHERE;
    }
    summary.cameraCount = scene.cameras.size();
    summary.variantNames = scene.variantNames;
    summary.variant = scene.variant;
    summary.environmentWidth = scene.environment.width;
    summary.environmentHeight = scene.environment.height;
    const SurfaceData& s = scene.surface;
    const bool textured = !s.uv0.empty() || !s.uv1.empty();
    summary.imageCount = textured ? s.images.size() : 0;
    summary.texelBytes = textured ? s.texelBytes() : 0;
    summary.smoothNormals = !s.normals.empty();
    summary.texcoord1 = !s.uv1.empty();
    summary.vertexColors = !s.colors.empty();
    summary.normalMaps = !s.tangents.empty();
    for (const Material& m : scene.materials) {
        summary.alphaMaskMaterials += (m.flags & WF_MATERIAL_ALPHA_MASK) != 0;
        summary.alphaBlendMaterials += (m.flags & WF_MATERIAL_ALPHA_BLEND) != 0;
        summary.transmissiveMaterials += m.transmission > 0.0f;
        summary.anisotropicMaterials += m.anisotropyStrength > 0.0f;
        summary.diffuseTransmissionMaterials += m.diffuseTransmission > 0.0f;
        summary.dispersiveMaterials += gpu_types::materialDisperses(m);
    }
    return summary;
}

std::string describe(const SceneSummary& summary) {
    std::string text = std::to_string(summary.triangleCount) + " triangles, " +
                       std::to_string(summary.materialCount) + " materials, " +
                       std::to_string(summary.emissiveTriangleCount) + " emissive triangles";
    if (summary.triangleCount > 0) {
        text += "; bounds " + formatVec(summary.boundsLo) + " to " + formatVec(summary.boundsHi);
    }
    text += "; lights: " + listCounts({{summary.pointLights, "point"},
                                       {summary.spotLights, "spot"},
                                       {summary.directionalLights, "directional"},
                                       {summary.sphereLights, "sphere"}},
                                      "none");
    text += "; environment: ";
    if (summary.environmentWidth == 0) {
        text += "none";
    } else if (summary.environmentWidth == 1 && summary.environmentHeight == 1) {
        text += "uniform";
    } else {
        text += std::to_string(summary.environmentWidth) + "x" +
                std::to_string(summary.environmentHeight) + " map";
    }
    text += "; cameras: " + std::to_string(summary.cameraCount);
    if (!summary.variantNames.empty()) { // KHR_materials_variants
        text += "; variants:";
        for (size_t i = 0; i < summary.variantNames.size(); ++i)
            text += (i ? ", " : " ") + std::to_string(i) + " '" + summary.variantNames[i] + "'" +
                    (int(i) == summary.variant ? " (chosen)" : "");
        if (summary.variant < 0)
            text += " (none chosen: the primitives' own materials)";
    }
    char texels[64];
    std::snprintf(texels, sizeof texels, " (%.1f MiB of texels)",
                  double(summary.texelBytes) / (1024.0 * 1024.0));
    text += "; textures: " + (summary.imageCount ? std::to_string(summary.imageCount) +
                                                       " images" + texels
                                                 : std::string("none"));
    std::string vertexData = summary.smoothNormals ? "smooth normals" : "";
    if (summary.imageCount > 0)
        vertexData += (vertexData.empty() ? "" : ", ") +
                      std::string(summary.texcoord1 ? "2 UV sets" : "UVs");
    if (summary.normalMaps)
        vertexData += ", tangents";
    if (summary.vertexColors)
        vertexData += (vertexData.empty() ? "" : ", ") + std::string("colours");
    text += "; vertex data: " + (vertexData.empty() ? "positions only" : vertexData);
    text += "; materials with " + listCounts({{summary.alphaMaskMaterials, "alpha mask"},
                                              {summary.alphaBlendMaterials, "alpha blend"},
                                              {summary.transmissiveMaterials, "transmission"},
                                              {summary.anisotropicMaterials, "anisotropic"},
                                              {summary.diffuseTransmissionMaterials,
                                               "diffuse transmission"},
                                              {summary.dispersiveMaterials, "dispersion"}},
                                             "no alpha or transmission");
    text += ".";
    const size_t lights = summary.pointLights + summary.spotLights + summary.directionalLights +
                          summary.sphereLights;
    if (summary.triangleCount == 0) {
        text += " The scene has no triangles.";
    } else if (!summary.hasEmitters && lights == 0 && summary.environmentWidth == 0) {
        text += " Nothing emits light: the image will be black.";
    }
    return text;
}

} // namespace wf
