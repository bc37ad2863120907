// Scene data as the GPU reads it (std430). Included by C++ and GLSL; the C++ side asserts the
// layout, so no struct is ever mirrored by hand.
#ifndef WF_SCENE_TYPES_H
#define WF_SCENE_TYPES_H

#include "glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

#define WF_NO_EMITTER 0xffffffffu

// A triangle in world space. vec3 + uint pack into 16 bytes in std430 and in C++ alike.
struct Triangle {
    vec3 p0;
    uint material;
    vec3 p1;
    uint emitter; // index into the emitter table, or WF_NO_EMITTER
    vec3 p2;
    uint pad;
};

// Flattened BVH node in depth-first order: an interior node's left child is the next node,
// its right child is `rightOrFirst`; a leaf holds `count` > 0 triangles from `rightOrFirst`.
struct BvhNode {
    vec3 lo;
    uint rightOrFirst;
    vec3 hi;
    uint count;
};

#define WF_MATERIAL_DOUBLE_SIDED 1u

struct Material {
    vec4 baseColor; // rgb: Lambert albedo (linear), a: unused
    vec3 emission;  // emissiveFactor x KHR_materials_emissive_strength
    uint flags;     // WF_MATERIAL_*
};

// One emissive triangle in the light table, chosen by power through a Walker alias table.
struct Emitter {
    uint triangle;
    float pmf;       // probability of choosing this emitter
    float aliasProb; // alias-table threshold for this slot
    uint alias;      // slot taken when the threshold test fails
};

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::Triangle) == 48);
static_assert(offsetof(wf::gpu_types::Triangle, p1) == 16);
static_assert(offsetof(wf::gpu_types::Triangle, emitter) == 28);
static_assert(offsetof(wf::gpu_types::Triangle, p2) == 32);
static_assert(sizeof(wf::gpu_types::BvhNode) == 32);
static_assert(offsetof(wf::gpu_types::BvhNode, hi) == 16);
static_assert(offsetof(wf::gpu_types::BvhNode, count) == 28);
static_assert(sizeof(wf::gpu_types::Material) == 32);
static_assert(offsetof(wf::gpu_types::Material, emission) == 16);
static_assert(offsetof(wf::gpu_types::Material, flags) == 28);
static_assert(sizeof(wf::gpu_types::Emitter) == 16);
#endif

#endif
