#version 460
// raygen: one camera path per (pixel, sample) of the wave.
// In: params (camera, image size), push constants (the wave's pixels and samples).
// Out: rayOrigin/rayDirection/throughput/radiance (and with WF_RAY_CONES rayCone) of every path;
// rayQueue[0] = path index.
// Path p is sample sampleBase + p / wavePixels of pixel pixelBase + p % wavePixels.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#include "sampling/rng.h"
#include "sampling/sampling.h"
#include "wave/wave_paths.glsl"
#include "wave/camera_ray.glsl"
#include "surface/ray_cones.glsl"
#if WF_HAS_DISPERSION
#include "bsdf/dispersion.h"
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT && WF_HAS_EMITTERS
#include "bidir/bdpt_state.glsl"
#endif
#if WF_GUIDING
#include "guiding/guide_bindings.glsl"
#include "guiding/guide_path.glsl"
#endif

layout(push_constant) uniform Push { PassConstants pass; };

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path >= pass.pathCount)
        return;
    vec3 origin, direction;
    cameraRay(wavePathPixel(pass, path), wavePathSample(pass, path), origin, direction);
    rayOrigin[path] = wfPack(vec4(origin, 0.0));
    rayDirection[path] = wfPack(vec4(direction, 0.0));
    throughput[path] = wfPack(vec4(1.0));
    radiance[path] = wfPack(vec4(0.0));
    rayQueues[path] = path;
#if WF_MOTION
    rayTime[path] = wfRayTime; // drawn by cameraRay
#endif
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
    for (uint j = 0u; j < WF_HERO_LANES; ++j)
        pathLanes[WF_HERO_LANES * path + j] = vec4(0.0); // RGB until its first dispersive vertex
#elif WF_HAS_DISPERSION
    pathWavelength[path] = 0.0; // RGB until its first dispersive vertex
#endif
#if WF_GUIDING
    guideStartPath(path);
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT && WF_HAS_EMITTERS
    pathMis[path] = bdptStored(bdptStartCamera(origin, direction, wavePathSample(pass, path)));
    // After the light subpaths, whose passes left the queue's arguments: the queue pass turns
    // this count into the camera rays' (wave_recorder.cpp).
    atomicAdd(counters.rayCount, 1u);
#endif
#if WF_RAY_CONES
    rayCone[path] = cameraCone();
#endif
}
