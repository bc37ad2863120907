// Lights that are not emissive triangles: KHR_lights_punctual point, spot and directional
// lights (Dirac deltas, reached only by next-event estimation) and sphere lights (a point light
// with extras.radius > 0: a sphere of uniform radiance intensity / (pi R^2), same power).
#ifndef WF_LIGHT_TYPES_H
#define WF_LIGHT_TYPES_H

#include "glsl_cpp.h"

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
    float pad1;
    float pad2;
};

// Read in shaders as RGBA32UI texels (scene_tables.glsl).
#define WF_PUNCTUAL_LIGHT_TEXELS 4u

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::PunctualLight) == 16 * WF_PUNCTUAL_LIGHT_TEXELS);
static_assert(offsetof(wf::gpu_types::PunctualLight, direction) == 16);
static_assert(offsetof(wf::gpu_types::PunctualLight, intensity) == 32);
static_assert(offsetof(wf::gpu_types::PunctualLight, cosInner) == 44);
#endif

#endif
