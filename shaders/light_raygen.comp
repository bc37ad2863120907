#version 460
// light_raygen (--integrator light, bdpt): the first ray of one light subpath per path of the wave
// whose pixel index is below params.lightPaths (bidir/light_share.glsl), after the camera's pass
// has found what each camera ray sees.
// In: params, the emitter table and lights, push constants (the wave: path p traces the light
// subpath of p's pixel and sample index, bidir/light_subpath.glsl).
// Out: rayOrigin/rayDirection/throughput of every path that carries light, appended to ray
// queue 0 (counters.rayCount; the queue pass turns it into the intersect's arguments).
// radiance[path] keeps the camera's value for the accumulate pass.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#if !WF_HAS_EMITTERS || WF_INTEGRATOR == WF_INTEGRATOR_PATH
#error "light_raygen exists only for light subpaths in scenes with emitters"
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
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
#include "bidir/bdpt_emitters.glsl"
#endif
#include "wave/wave_paths.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

WF_DEFINE_QUEUE_APPEND(appendRay, counters.rayCount)

void main() {
    uint path = gl_GlobalInvocationID.x;
    bool emits = false;
    if (path < pass.pathCount && tracesLightSubpath(path % pass.wavePixels)) {
        EmittedRay ray;
#if WF_MOTION
        // The camera subpath's time (camera_ray.glsl's dimension): both subpaths of a sample,
        // and every connection between them, see the scene at one instant.
        wfRayTime = sample1D(wavePathPixel(pass, path), wavePathSample(pass, path), WF_DIM_TIME,
                             params.seed);
        rayTime[path] = wfRayTime;
#endif
        emits = emitLightRay(wavePathPixel(pass, path), wavePathSample(pass, path), ray);
        if (emits) {
            rayOrigin[path] = wfPack(vec4(ray.origin, 0.0));
            rayDirection[path] = wfPack(vec4(ray.direction, 0.0));
            // w: the emitted throughput's largest channel, what Russian roulette measures
            // the subpath's throughput against (light_shade.comp).
            throughput[path] =
                wfPack(vec4(ray.beta, max(ray.beta.r, max(ray.beta.g, ray.beta.b))));
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
            bdptStartLightSubpath(path, ray);
#endif
        }
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
        lightDepths[path] = 0u;
#endif
    }
    // In uniform control flow: every lane of the subgroup takes part.
    uint slot = appendRay(emits);
    if (emits)
        rayQueues[slot] = path;
}
