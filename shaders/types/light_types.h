// Lights that are not emissive triangles: KHR_lights_punctual point, spot and directional
// lights (Dirac deltas, reached only by next-event estimation) and sphere lights (a point light
// with extras.radius > 0: a sphere of uniform radiance intensity / (pi R^2), same power).
#ifndef WF_LIGHT_TYPES_H
#define WF_LIGHT_TYPES_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

#define WF_LIGHT_POINT 0u
#define WF_LIGHT_SPOT 1u
#define WF_LIGHT_DIRECTIONAL 2u
#define WF_LIGHT_SPHERE 3u

struct PunctualLight {
    vec3 position;   // world space (unused for directional)
    uint type;       // WF_LIGHT_*
    vec3 direction;  // unit, the direction light travels (spot, directional)
    float radius;    // sphere lights only
    vec3 intensity;  // colour x intensity: W/sr (point, spot), W/m^2 = lux (directional),
                     // radiance intensity / (pi R^2) is derived for spheres
    float cosInner;  // spot: cos(innerConeAngle)
    float cosOuter;  // spot: cos(outerConeAngle)
    uint emitter;    // this light's entry in the emitter table (for MIS when a ray hits it)
    // WF_MOTION: 0 for a still light, else 1 + its first key in the motion-key table (one
    // position per key); zero-initialised lights are still.
    uint motion;
    float pad2;
};

// Read in shaders as RGBA32UI texels (scene_tables.glsl).
#define WF_PUNCTUAL_LIGHT_TEXELS 4u

// LightTreeNode.child: a leaf holds one emitter-table entry.
#define WF_LIGHT_TREE_LEAF 0x80000000u
#define WF_LIGHT_TREE_MAX_DEPTH 64u // trails are 64 bits

struct LightTreeNode {
    vec3 lo;          // bounds of the lights' surfaces (a point light's position)
    float power;      // the lights' summed power estimate (the light table's)
    vec3 hi;
    uint child;       // interior: the second child (the first is this + 1); leaf: LEAF | emitter
    vec3 axis;        // unit: the cone of normals (directions of emission) is around it ...
    float cosThetaO;  // ... with half-angle thetaO
    float cosThetaE;  // and light leaves each normal within thetaE of it
    uint twoSided;    // 1: emission leaves both faces (the cone and its opposite)
    float pad0;
    float pad1;
};

#define WF_LIGHT_TREE_NODE_TEXELS 4u

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::PunctualLight) == 16 * WF_PUNCTUAL_LIGHT_TEXELS);
static_assert(offsetof(wf::gpu_types::PunctualLight, direction) == 16);
static_assert(offsetof(wf::gpu_types::PunctualLight, intensity) == 32);
static_assert(offsetof(wf::gpu_types::PunctualLight, cosInner) == 44);
static_assert(sizeof(wf::gpu_types::LightTreeNode) == 16 * WF_LIGHT_TREE_NODE_TEXELS);
static_assert(offsetof(wf::gpu_types::LightTreeNode, hi) == 16);
static_assert(offsetof(wf::gpu_types::LightTreeNode, axis) == 32);
static_assert(offsetof(wf::gpu_types::LightTreeNode, cosThetaE) == 48);
#endif

#endif
