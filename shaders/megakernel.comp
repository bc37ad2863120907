#version 460
// megakernel: the baseline the wavefront must beat. One invocation traces a whole path with the
// very functions the passes call (cameraRay, intersectClosest, shadePathVertex,
// segmentOccluded), so both trace the same samples; only the schedule differs.
// In: params, scene, lights, push constants (the wave). Out: radiance[path] (then the
// accumulate pass), counters' ray statistics as the queue pass would have kept them.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
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
#include "traversal/scene_intersect.glsl"
#include "wave/wave_paths.glsl"
#include "wave/camera_ray.glsl"
#extension GL_KHR_shader_subgroup_arithmetic : require

layout(push_constant) uniform Push { PassConstants pass; };

// One atomicAdd per subgroup, in uniform control flow.
void addCount(uint n, uint field) {
    uint total = subgroupAdd(n);
    if (total > 0u && subgroupElect()) {
        if (field < WF_TRACKED_DEPTHS)
            atomicAdd(counters.depthRays[field], total);
        else
            atomicAdd(counters.depthShadowRays[field - WF_TRACKED_DEPTHS], total);
    }
}

void main() {
    uint path = gl_GlobalInvocationID.x;
    bool live = path < pass.pathCount;
    uint lastDepth = 0u;   // the deepest bounce whose ray was traced
    uint shadowBits = 0u;  // bit d: a connection at depth d < WF_TRACKED_DEPTHS - 1
    uint deepShadows = 0u; // connections at deeper bounces
    if (live) {
        PathVertex v;
        v.pixel = wavePathPixel(pass, path);
        v.sampleIndex = wavePathSample(pass, path);
        cameraRay(v.pixel, v.sampleIndex, v.origin, v.direction);
        v.previousPdf = 0.0;
        v.previousNormal = 0.0;
        v.beta = vec3(1.0);
        v.etaScale = 1.0;
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
        for (uint j = 0u; j < WF_HERO_LANES; ++j)
            v.lanes[j] = vec4(0.0); // RGB until its first dispersive vertex
#elif WF_HAS_DISPERSION
        v.wavelength = 0.0; // RGB until its first dispersive vertex
#endif
#if WF_RAY_CONES
        v.cone = cameraCone();
#endif
        vec3 total = vec3(0.0);
#if WF_GUIDING
        v.path = path;
        guideStartPath(path);
#endif
        // Same order of additions as shade then shadow, so sums round alike.
        for (uint depth = 0u; depth < params.maxDepth; ++depth) {
            lastDepth = depth;
            v.depth = depth;
            v.hit = intersectClosest(v.origin, v.direction);
#if WF_GUIDING
            guideTakeRadianceBefore(path, total);
#endif
            shadePathVertex(v);
            total += v.radiance;
#if WF_HAS_EMITTERS
            if (v.connects) {
                if (depth < WF_TRACKED_DEPTHS - 1u)
                    shadowBits |= 1u << depth;
                else
                    ++deepShadows;
                if (!segmentOccluded(v.shadowOrigin, v.shadowSegment, v.shadowSphere))
                    total += v.shadowRadiance;
            }
#endif
            if (!v.continues)
                break;
        }
        radiance[path] = wfPack(vec4(total, 0.0));
    }

    // Statistics as the wavefront keeps them: rays traced per depth, connections per depth.
    uint extension = live ? lastDepth : 0u;
    uint shadows = bitCount(shadowBits) + deepShadows;
    uint extensionTotal = subgroupAdd(extension);
    uint shadowTotal = subgroupAdd(shadows);
    if (subgroupElect()) {
        atomicAdd(counters.extensionRays, extensionTotal);
        atomicAdd(counters.shadowRays, shadowTotal);
    }
    const uint last = WF_TRACKED_DEPTHS - 1u;
    for (uint d = 1u; d < WF_TRACKED_DEPTHS; ++d) {
        uint alive = !live || lastDepth < d ? 0u : (d < last ? 1u : lastDepth - last + 1u);
        addCount(alive, d);
        addCount(d - 1u < last ? (shadowBits >> (d - 1u)) & 1u : 0u, WF_TRACKED_DEPTHS + d - 1u);
    }
    addCount(deepShadows, WF_TRACKED_DEPTHS + last);
}
