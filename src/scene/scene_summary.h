// A few numbers about a loaded scene, for the log and for catching an unlit or empty scene
// before spending GPU time on it.
#pragma once
#include <cstddef>
#include <string>

#include "scene/scene.h"

namespace wf {

struct SceneSummary {
    size_t triangleCount = 0;
    size_t materialCount = 0;
    size_t emissiveTriangleCount = 0; // triangles whose material has non-zero emission
    bool hasEmitters = false;
    glm::vec3 boundsLo{0.0f}; // world-space bounds of all vertices; both 0 if no triangles
    glm::vec3 boundsHi{0.0f};
};

SceneSummary summarize(const Scene& scene);

// One paragraph for people, e.g. "36 triangles, 4 materials, 2 emissive triangles; bounds
// (0, 0, 0) to (5.55, 5.55, 5.55)." It adds a warning when nothing emits light.
std::string describe(const SceneSummary& summary);

} // namespace wf
