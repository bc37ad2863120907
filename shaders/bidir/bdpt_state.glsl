// Bidirectional path tracing in the wavefront (--integrator bdpt, issue 46): the state one
// wave carries between its light and camera subpaths, and the connections between them.
// Each path slot traces a light subpath first (light_raygen, light_shade), whose non-Dirac
// vertices are kept here, then its camera subpath (raygen, shade), whose vertices connect to
// every kept vertex of the slot's own light subpath. Every strategy (s, t) is weighed by
// bidir/vcm_mis.h's running quantities (Georgiev's dVCM, dVC), kept per path in pathMis.
// Includers provide bindings, geometry, rng, sampling, light_sampling, bsdf, surface, lights
// and (for the connections) wave/path_vertex.glsl and bidir/adjoint_bsdf.h.
#ifndef WF_BDPT_STATE_GLSL
#define WF_BDPT_STATE_GLSL
#include "bidir/vcm_mis.h"
#include "bidir/scene_camera.glsl"
#include "bidir/light_share.glsl"
#if WF_VCM
#include "bidir/vcm_grid.glsl"
#endif

// 2: the power heuristic, 1: the balance heuristic.
#ifndef WF_BDPT_MIS_EXPONENT
#define WF_BDPT_MIS_EXPONENT 2.0
#endif

layout(std430, binding = WF_BINDING_PATH_MIS) buffer PathMisBuffer {
    // Per path: dVCM, dVC, dVM of the subpath's last vertex. Between light_raygen and the light
    // subpath's first hit: emission pdf, cos at the light, 0 and the emitter (as float bits).
    vec4 pathMis[];
};
layout(std430, binding = WF_BINDING_LIGHT_DEPTHS) buffer LightDepthBuffer {
    uint lightDepths[]; // per path: light bounces whose slot below is written (0 .. n - 1)
};
// Per light vertex, at slot d pathCapacity + path for light bounce d (a vertex its light
// subpath's ray d + 1 found): its hit; its unit direction towards the light side and dVCM;
// its throughput (0: a Dirac vertex, which nothing connects to) and dVC.
layout(std430, binding = WF_BINDING_LIGHT_VERTEX_HITS) buffer LightVertexHitBuffer {
    uvec4 lightVertexHits[];
};
layout(std430, binding = WF_BINDING_LIGHT_VERTEX_DIRECTIONS) buffer LightVertexDirectionBuffer {
    vec4 lightVertexDirections[];
};
layout(std430, binding = WF_BINDING_LIGHT_VERTEX_THROUGHPUTS) buffer LightVertexThroughputBuffer {
    vec4 lightVertexThroughputs[];
};

// Light subpaths per sample index: one per pixel (camera_importance.h's splat scale 1). With
// merging (WF_VCM), sample index i merges them within its own radius (vcm_grid.glsl).
VcmMisConfig bdptMisConfig(uint sampleIndex) {
#if WF_VCM
    float radius = vcmMergeRadius(sampleIndex);
    return makeVcmMisConfig(WF_BDPT_MIS_EXPONENT, float(params.lightPaths),
                            WF_PI * radius * radius * float(params.lightPaths), true, true);
#else
    return makeVcmMisConfig(WF_BDPT_MIS_EXPONENT, float(params.lightPaths), 0.0, true, false);
#endif
}

VcmSubpathMis bdptMis(vec4 stored) {
    VcmSubpathMis mis;
    mis.dVCM = stored.x;
    mis.dVC = stored.y;
    mis.dVM = stored.z;
    return mis;
}

vec4 bdptStored(VcmSubpathMis mis) { return vec4(mis.dVCM, mis.dVC, mis.dVM, 0.0); }

// The camera subpath's start: its ray's density per pixel, W H cameraDirectionPdf.
VcmSubpathMis bdptStartCamera(vec3 lensPoint, vec3 direction, uint sampleIndex) {
    return vcmStartCamera(bdptMisConfig(sampleIndex),
                          float(params.pixelCount) *
                              cameraDirectionPdf(sceneCamera(), lensPoint, direction));
}

// Light bounces whose vertices are kept: a camera vertex at bounce 0 connects to bounce d as
// a path of d + 3 segments, or merges with it as one of d + 2.
bool bdptKeepsLightVertex(uint depth) {
    return depth + (WF_VCM != 0 ? 2u : 3u) <= params.maxDepth;
}

// beta 0: a Dirac vertex, which nothing connects to or merges with.
void bdptStoreLightVertex(uint path, uint depth, uvec4 hit, vec3 p, vec3 toLight, vec3 beta,
                          VcmSubpathMis mis, uint sampleIndex) {
    uint slot = depth * params.pathCapacity + path;
    lightVertexHits[slot] = hit;
    lightVertexDirections[slot] = vec4(toLight, mis.dVCM);
    lightVertexThroughputs[slot] = vec4(beta, mis.dVC);
#if WF_VCM
    if (any(greaterThan(beta, vec3(0.0))))
        vcmInsertLightVertex(slot, p, mis.dVM, sampleIndex);
#endif
}

#endif
