#version 460
// light_raygen (--integrator light): the first ray of one light subpath per path of the wave,
// after the camera's pass has found what each camera ray sees.
// In: params, the emitter table and lights, push constants (the wave: path p traces the light
// subpath of p's pixel and sample index, bidir/light_subpath.glsl).
// Out: rayOrigin/rayDirection/throughput of every path that carries light, appended to ray
// queue 0 (counters.rayCount; the queue pass turns it into the intersect's arguments).
// radiance[path] keeps the camera's value for the accumulate pass.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#if !WF_HAS_EMITTERS || WF_INTEGRATOR != WF_INTEGRATOR_LIGHT
#error "light_raygen exists only for light tracing in scenes with emitters"
#endif
#include "wave/queue_append.glsl"
#include "traversal/geometry.h"
#include "sampling/rng.h"
#include "sampling/sampling.h"
#include "lights/light_sampling.h"
#include "bsdf/bsdf.h"
#include "surface/surface.glsl"
#include "lights/lights.glsl"
#include "bidir/light_subpath.glsl"
#include "wave/wave_paths.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

WF_DEFINE_QUEUE_APPEND(appendRay, counters.rayCount)

void main() {
    uint path = gl_GlobalInvocationID.x;
    bool emits = false;
    if (path < pass.pathCount) {
        vec3 origin, direction, beta;
        emits = emitLightRay(wavePathPixel(pass, path), wavePathSample(pass, path), origin,
                             direction, beta);
        if (emits) {
            rayOrigin[path] = wfPack(vec4(origin, 0.0));
            rayDirection[path] = wfPack(vec4(direction, 0.0));
            throughput[path] = wfPack(vec4(beta, 1.0));
        }
    }
    // In uniform control flow: every lane of the subgroup takes part.
    uint slot = appendRay(emits);
    if (emits)
        rayQueues[slot] = path;
}
