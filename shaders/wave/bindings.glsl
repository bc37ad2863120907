// Buffer declarations of the shared descriptor set. The host compiles each scene's variant with
// switches saying what exists (WF_HAS_EMITTERS: a light table for next-event estimation;
// WF_HAS_LIGHTS: sphere or Dirac lights; WF_HAS_ENVIRONMENT: an environment map), so a scene
// declares and binds only the buffers it reads.
#if WF_PACKED_STORES
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
// 16-byte path-state entries as two 64-bit words, stored through wfPack: lavapipe stores a
// storage buffer one component and one lane at a time, so wider components mean fewer of its
// loops (+7% paths/s on the Cornell box). The texel views read the same bytes either way.
#define WfEntry u64vec2
#define WfUintEntry u64vec2
#else
#define WfEntry vec4
#define WfUintEntry uvec4
#endif
#include "types/scene_types.h"
#include "types/render_types.h"
#include "types/light_types.h"

#include "tables/scene_tables.glsl"
// A uniform buffer: every invocation reads the same words (std140 lays RenderParams out as
// std430 does; tests/unit/test_shared_layout.cpp checks it).
layout(std140, binding = WF_BINDING_PARAMS) uniform ParamsBuffer {
    RenderParams params;
};
layout(std430, binding = WF_BINDING_COUNTERS) buffer CounterBuffer {
    QueueCounters counters;
};
layout(std430, binding = WF_BINDING_FILM) buffer FilmBuffer {
    vec4 film[]; // rgb: radiance sum, a: sample count
};
layout(std430, binding = WF_BINDING_RAY_ORIGIN) buffer RayOriginBuffer {
    WfEntry rayOrigin[]; // xyz: origin, w: pdf of the BSDF sample that chose the ray (0: none)
};
layout(std430, binding = WF_BINDING_RAY_DIRECTION) buffer RayDirectionBuffer {
    // xyz: unit direction, w: the light tree's receiver normal at the vertex it left
    // (encodeReceiverNormal; 0: none)
    WfEntry rayDirection[];
};
layout(std430, binding = WF_BINDING_THROUGHPUT) buffer ThroughputBuffer {
    WfEntry throughput[];
};
#if WF_AOV
// --aov: the camera ray's first hit per path, [2 path] = (albedo, distance), [2 path + 1] =
// (shading normal, 0), zero where it hits no surface; and per pixel the sums of those,
// [2 pixel + 0, 1], beside the film.
layout(std430, binding = WF_BINDING_AOV_PATHS) buffer AovPathBuffer {
    vec4 aovPath[];
};
layout(std430, binding = WF_BINDING_AOV_FILM) buffer AovFilmBuffer {
    vec4 aovFilm[];
};
#endif
#if WF_SECOND_MOMENT
layout(std430, binding = WF_BINDING_MOMENT_FILM) buffer MomentFilmBuffer {
    vec4 momentFilm[]; // rgb: sum of radiance squared, beside the film's sum; a: largest sample
};
#endif
#if defined(WF_ERROR_REPLICATES) && WF_ERROR_REPLICATES > 1
// Per pixel, K - 1 entries: replicate r's rgb sum and sample count at [pixel (K - 1) + r - 1].
// Replicate 0's are the film's less theirs (rng.h says which samples a replicate holds).
layout(std430, binding = WF_BINDING_REPLICATE_FILM) buffer ReplicateFilmBuffer {
    vec4 replicateFilm[];
};
#endif
#if WF_ADAPTIVE
layout(std430, binding = WF_BINDING_ACTIVE_PIXELS) readonly buffer ActivePixelBuffer {
    uint activePixels[]; // image pixel indices, in the order waves cover them
};
#endif
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
layout(std430, binding = WF_BINDING_PATH_WAVELENGTH) buffer PathLaneBuffer {
    vec4 pathLanes[]; // [4 path + j]: lane j's (share, wavelength) (wave/hero_lanes.glsl)
};
#elif WF_HAS_DISPERSION
layout(std430, binding = WF_BINDING_PATH_WAVELENGTH) buffer PathWavelengthBuffer {
    float pathWavelength[]; // nm; 0 while the path is RGB (bsdf/dispersion.h)
};
#endif
#if WF_RAY_CONES
layout(std430, binding = WF_BINDING_RAY_CONES) buffer RayConeBuffer {
    vec2 rayCone[]; // x: the cone's width at the ray's origin, y: its spread angle (radians)
};
#endif
layout(std430, binding = WF_BINDING_RADIANCE) buffer RadianceBuffer {
    WfEntry radiance[];
};
layout(std430, binding = WF_BINDING_HITS) buffer HitBuffer {
    WfUintEntry hits[]; // t, b1, b2 as float bits; triangle index, or WF_MISS
};
layout(std430, binding = WF_BINDING_RAY_QUEUES) buffer RayQueueBuffer {
    uint rayQueues[]; // two queues of pathCapacity path indices, by depth parity
};
#if WF_SHADE_BINS > 1
layout(std430, binding = WF_BINDING_KIND_QUEUES) buffer KindQueueBuffer {
    uint kindQueues[]; // per shade bin, pathCapacity slots of the current ray queue
};
#endif
#if WF_HAS_EMITTERS
// The shadow queue is these three arrays, by slot: the record carries the path it connects, so
// the pass that appends it stores no separate queue entry (one store loop fewer on lavapipe).
layout(std430, binding = WF_BINDING_SHADOW_ORIGIN) buffer ShadowOriginBuffer {
    WfUintEntry shadowOrigin[]; // xyz: origin as float bits, w: the path
};
layout(std430, binding = WF_BINDING_SHADOW_DIRECTION) buffer ShadowDirectionBuffer {
    // xyz: target - origin, so the segment is t in (0, 1); w: 1 + the sphere light it ends on
    // as a float (exact below 2^24; raw bits could be denormals, which a device may flush), 0
    // when it ends elsewhere: uint(w) - 1 is that light or WF_NO_SPHERE.
    WfEntry shadowDirection[];
};
layout(std430, binding = WF_BINDING_SHADOW_RADIANCE) buffer ShadowRadianceBuffer {
    WfEntry shadowRadiance[]; // radiance added if the segment is unoccluded
};
#endif
#include "wave/path_texels.glsl"
#if WF_PACKED_STORES
u64vec2 wfPack(uvec4 v) { return u64vec2(packUint2x32(v.xy), packUint2x32(v.zw)); }
u64vec2 wfPack(vec4 v) { return wfPack(floatBitsToUint(v)); }
#else
uvec4 wfPack(uvec4 v) { return v; }
vec4 wfPack(vec4 v) { return v; }
#endif

#define WF_MISS 0xffffffffu
#define WF_SPHERE_HIT 0x80000000u // hits.w = WF_SPHERE_HIT | sphere light index
#define WF_NO_SPHERE 0xffffffffu

// instanceAt and lightAt: the records at the path's time (motion.glsl).
#include "wave/motion.glsl"
