#version 460
// shade: one path vertex (shaders/wave/path_vertex.glsl) per ray in the current queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), hits (by queue slot), path state,
// scene, lights.
// Out: radiance += emission the ray found; appends the path to the shadow queue with a
// next-event connection (shadowOrigin/Direction/Radiance at its queue slot) and to
// rayQueue[(depth + 1) & 1] with its BSDF-sampled continuation (rayOrigin/Direction,
// throughput and with WF_RAY_CONES rayCone, by path).
// Shaded by kind (WF_SHADE_BIN defined): only the slots of that bin, kindQueues[WF_SHADE_BIN]
// (count in counters.kindCount[WF_SHADE_BIN]), with the BSDF of its kind compiled in.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#include "wave/queue_append.glsl"
#include "traversal/geometry.h"
#include "sampling/rng.h"
#include "sampling/sampling.h"
#include "lights/light_sampling.h"
#include "bsdf/bsdf.h"
#include "surface/surface.glsl"
#include "lights/lights.glsl"
#if WF_GUIDING
#include "guiding/guide_bindings.glsl"
#include "guiding/guide_path.glsl"
#endif
#include "wave/path_vertex.glsl"
#include "wave/wave_paths.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

WF_DEFINE_QUEUE_APPEND(appendRay, counters.rayCount)
#if WF_HAS_EMITTERS
WF_DEFINE_QUEUE_APPEND(appendShadow, counters.shadowCount)
#endif

void main() {
#ifdef WF_SHADE_BIN
    // The queue slot, not the bin's entry, indexes the hits.
    bool inQueue = gl_GlobalInvocationID.x < counters.kindCount[WF_SHADE_BIN];
    uint index = inQueue ? kindQueueAt(WF_SHADE_BIN, gl_GlobalInvocationID.x) : 0u;
#else
    uint index = gl_GlobalInvocationID.x;
    bool inQueue = index < counters.rayArgs.count;
#endif
    uint path = inQueue ? rayQueueAt(pass.depth, index) : 0u;
    PathVertex v;
    v.continues = false;
    v.connects = false;
    if (inQueue) {
        v.pixel = wavePathPixel(pass, path);
        v.sampleIndex = wavePathSample(pass, path);
        v.depth = pass.depth;
#if WF_MOTION
        wfRayTime = rayTime[path];
#endif
#if WF_GUIDING
        v.path = path;
        guideTakeRadianceBefore(path, radianceAt(path).rgb);
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
        v.path = path;
        v.mis = pathMis[path];
#endif
        v.hit = hitAt(index);
        vec4 origin = rayOriginAt(path);
        v.origin = origin.xyz;
        v.previousPdf = origin.w;
        vec4 direction = rayDirectionAt(path);
        v.direction = direction.xyz;
        v.previousNormal = direction.w;
        vec4 pathThroughput = throughputAt(path);
        v.beta = pathThroughput.rgb;
        v.etaScale = pathThroughput.w;
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
        for (uint j = 0u; j < WF_HERO_LANES; ++j)
            v.lanes[j] = pathLanes[WF_HERO_LANES * path + j];
#elif WF_HAS_DISPERSION
        v.wavelength = pathWavelength[path];
#endif
#if WF_RAY_CONES
        v.cone = rayConeAt(path);
#endif
#if WF_AOV
        v.aovAlbedoDistance = vec4(0.0);
        v.aovNormal = vec3(0.0);
#endif
        shadePathVertex(v);
#if WF_AOV
        if (pass.depth == 0u) {
            aovPath[2u * path] = v.aovAlbedoDistance;
            aovPath[2u * path + 1u] = vec4(v.aovNormal, 0.0);
        }
#endif
        // Stores cost a loop over the lanes on lavapipe: skip the ones that change nothing
        // (most vertices find no emission).
        if (any(notEqual(v.radiance, vec3(0.0))))
            radiance[path] = wfPack(vec4(radianceAt(path).rgb + v.radiance, 0.0));
        if (v.continues) {
            rayOrigin[path] = wfPack(vec4(v.origin, v.previousPdf));
            rayDirection[path] = wfPack(vec4(v.direction, v.previousNormal));
            throughput[path] = wfPack(vec4(v.beta, v.etaScale));
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
            for (uint j = 0u; j < WF_HERO_LANES; ++j)
                pathLanes[WF_HERO_LANES * path + j] = v.lanes[j];
#elif WF_HAS_DISPERSION
            pathWavelength[path] = v.wavelength;
#endif
#if WF_RAY_CONES
            rayCone[path] = v.cone;
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
            pathMis[path] = v.mis;
#endif
        }
    }
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    // Not a surface: nothing to connect (shadePathVertex sets it only at surfaces).
    if (!inQueue || v.hit.w == WF_MISS || (v.hit.w & WF_SPHERE_HIT) != 0u)
        bdptVertex.connectable = false;
#endif

    // Appends happen in uniform control flow: every lane of the subgroup takes part.
    uint raySlot = appendRay(v.continues);
    if (v.continues)
        rayQueues[((pass.depth + 1u) & 1u) * params.pathCapacity + raySlot] = path;
#if WF_HAS_EMITTERS
    uint shadowSlot = appendShadow(v.connects);
    if (v.connects) {
        // By queue slot, so that the shadow pass reads its connections in order; the path
        // rides in the origin's w.
        shadowOrigin[shadowSlot] = wfPack(uvec4(floatBitsToUint(v.shadowOrigin), path));
        shadowDirection[shadowSlot] =
            wfPack(vec4(v.shadowSegment, float(v.shadowSphere + 1u)));
        // w: the path's time, for bdpt's light_splat (shadow.comp reads it by path).
        shadowRadiance[shadowSlot] = wfPack(vec4(v.shadowRadiance, pathTime()));
    }
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    // The connections to the path slot's light vertices, one light bounce at a time, so that
    // every lane takes part in each append; light_splat tests them and adds them to the
    // path's light film entry (several per path: its adds are atomic). The light subpath is
    // the one its pixel shares in its sample's slots (bidir/light_share.glsl).
    uint lightPath = path - path % pass.wavePixels + lightSubpathOfPixel(path % pass.wavePixels);
    for (uint d = 0u; d + 3u <= params.maxDepth; ++d) {
        vec3 origin, segment, value;
        bool connects = inQueue && bdptConnect(bdptVertex, lightPath, pass.depth, d, origin,
                                               segment, value);
        uint slot = appendShadow(connects);
        if (connects) {
            shadowOrigin[slot] = wfPack(uvec4(floatBitsToUint(origin), path));
            shadowDirection[slot] = wfPack(vec4(segment, 0.0));
            shadowRadiance[slot] = wfPack(vec4(value, pathTime()));
        }
    }
#if WF_VCM
    // Merges need no visibility test: straight into the path's light film entry.
    if (inQueue && bdptVertex.connectable) {
        LightFilmSum merged = vcmMerge(bdptVertex, path, pass.depth, pass.wavePixels);
        lightFilmAddSum(path, merged);
    }
#endif
#endif
}
