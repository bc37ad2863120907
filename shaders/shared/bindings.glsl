// Buffer declarations of the shared descriptor set. The host compiles each scene's variant with
// switches saying what exists (WF_HAS_EMITTERS: a light table for next-event estimation;
// WF_HAS_LIGHTS: sphere or Dirac lights; WF_HAS_ENVIRONMENT: an environment map), so a scene
// declares and binds only the buffers it reads.
#include "scene_types.h"
#include "render_types.h"
#include "light_types.h"

#include "scene_tables.glsl"
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
    vec4 rayOrigin[]; // xyz: origin, w: pdf of the BSDF sample that chose the ray (0: none)
};
layout(std430, binding = WF_BINDING_RAY_DIRECTION) buffer RayDirectionBuffer {
    vec4 rayDirection[]; // xyz: unit direction
};
layout(std430, binding = WF_BINDING_THROUGHPUT) buffer ThroughputBuffer {
    vec4 throughput[];
};
layout(std430, binding = WF_BINDING_RADIANCE) buffer RadianceBuffer {
    vec4 radiance[];
};
layout(std430, binding = WF_BINDING_HITS) buffer HitBuffer {
    uvec4 hits[]; // t, b1, b2 as float bits; triangle index, or WF_MISS
};
layout(std430, binding = WF_BINDING_RAY_QUEUES) buffer RayQueueBuffer {
    uint rayQueues[]; // two queues of pathCapacity path indices, by depth parity
};
#if WF_HAS_EMITTERS
layout(std430, binding = WF_BINDING_SHADOW_ORIGIN) buffer ShadowOriginBuffer {
    vec4 shadowOrigin[];
};
layout(std430, binding = WF_BINDING_SHADOW_DIRECTION) buffer ShadowDirectionBuffer {
    vec4 shadowDirection[]; // xyz: target - origin, so the segment is t in (0, 1)
};
layout(std430, binding = WF_BINDING_SHADOW_RADIANCE) buffer ShadowRadianceBuffer {
    vec4 shadowRadiance[]; // radiance added if the segment is unoccluded
};
layout(std430, binding = WF_BINDING_SHADOW_QUEUE) buffer ShadowQueueBuffer {
    uint shadowQueue[];
};
#endif
#include "path_texels.glsl"

#define WF_MISS 0xffffffffu
#define WF_SPHERE_HIT 0x80000000u // hits.w = WF_SPHERE_HIT | sphere light index
