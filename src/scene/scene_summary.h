// What a loaded scene contains and which features it uses, for --verbose and for catching an
// unlit or empty scene before spending GPU time on it. The shader variant is chosen from the
// same data (src/render/shader_variant.cpp, surface_buffers.cpp), so what this prints is what
// the GPU gets.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace wf {

struct SceneSummary {
    size_t triangleCount = 0;
    size_t materialCount = 0;
    size_t emissiveTriangleCount = 0; // triangles whose material has non-zero emission
    bool hasEmitters = false;
    glm::vec3 boundsLo{0.0f}; // world-space bounds of all vertices; both 0 if no triangles
    glm::vec3 boundsHi{0.0f};
    // Lights beyond emissive triangles, by WF_LIGHT_* type.
    size_t pointLights = 0, spotLights = 0, directionalLights = 0, sphereLights = 0;
    size_t cameraCount = 0;
    std::vector<std::string> variantNames; // KHR_materials_variants, in file order
    int variant = -1;                      // the one chosen (--variant); -1: none
    uint32_t environmentWidth = 0, environmentHeight = 0; // 1x1: the uniform default
    // Surface features: each switches on shader code and GPU buffers.
    size_t imageCount = 0;
    uint64_t texelBytes = 0;
    bool smoothNormals = false;
    bool texcoord1 = false;
    bool vertexColors = false; // COLOR_0
    bool normalMaps = false;
    size_t alphaMaskMaterials = 0, alphaBlendMaterials = 0, transmissiveMaterials = 0;
    size_t anisotropicMaterials = 0; // KHR_materials_anisotropy (WF_HAS_ANISOTROPY)
    size_t diffuseTransmissionMaterials = 0; // KHR_materials_diffuse_transmission
    size_t dispersiveMaterials = 0; // KHR_materials_dispersion on glass (WF_HAS_DISPERSION)
    double loadSeconds = 0.0; // reading and converting the file; set by whoever timed it
};

SceneSummary summarize(const Scene& scene);

// One paragraph for people, e.g. "36 triangles, 4 materials, 2 emissive triangles; bounds
// (0, 0, 0) to (5.55, 5.55, 5.55); lights: none; textures: none; ...". It adds a warning
// when nothing emits light.
std::string describe(const SceneSummary& summary);

} // namespace wf
