#version 460
// light_shade (--integrator light, bdpt): one vertex of a light subpath per ray in the current queue.
// The vertex connects to the camera (a splat, queued for the light_splat pass's visibility
// test) unless its BSDF is Dirac, and continues by sampling the adjoint BSDF
// (bidir/adjoint_bsdf.h) with Russian roulette. Light subpaths collect no emission: paths that
// end on an emitter seen by the camera are the camera pass's (emitters seen directly).
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), hits (by queue slot), the light
// subpaths' rays and throughput (by path), the scene.
// Out: the continuation (rayOrigin/rayDirection/throughput by path, appended to
// rayQueue[(depth + 1) & 1]); camera connections in the shadow queue's arrays by slot: origin
// with the light film entry in w, the segment to the lens point, the value to splat.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#if !WF_HAS_EMITTERS || WF_INTEGRATOR == WF_INTEGRATOR_PATH
#error "light_shade exists only for light tracing in scenes with emitters"
#endif
#include "wave/queue_append.glsl"
#include "traversal/geometry.h"
#include "sampling/rng.h"
#include "sampling/sampling.h"
#include "lights/light_sampling.h"
#include "bsdf/bsdf.h"
#include "surface/surface.glsl"
#include "lights/lights.glsl"
#include "wave/path_vertex.glsl"
#include "bidir/adjoint_bsdf.h"
#include "bidir/light_subpath.glsl"
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
#include "bidir/bdpt_emitters.glsl"
#endif
#include "wave/wave_paths.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

WF_DEFINE_QUEUE_APPEND(appendRay, counters.rayCount)
WF_DEFINE_QUEUE_APPEND(appendSplat, counters.shadowCount)

struct LightVertex {
    // In: where the subpath is.
    uint pixel;       // the path slot's pixel and sample index: its sample dimensions
    uint sampleIndex;
    uint depth;       // light bounce index: this ray is the subpath's segment depth + 1
    uvec4 hit;
    // In and out: the ray, and after shading the continuation.
    vec3 origin;
    vec3 direction;   // the way light travels
    vec3 beta;        // emitted cos / pdfs x the adjoint BSDF's sample weights so far
    float betaStart;  // the largest channel of beta as emitted (Russian roulette's scale)
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    uint path;
    vec4 mis;         // pathMis: the subpath's MIS quantities (bdpt_state.glsl), in and out
#endif
    // Out.
    bool continues;
    bool connects;
    vec3 splatOrigin;
    vec3 splatSegment; // to the lens point: t in (0, 1)
    uint splatPixel;
    vec3 splat;        // added to splatPixel if the segment is unoccluded
};

void shadeLightVertex(inout LightVertex v) {
    v.continues = false;
    v.connects = false;
    if (v.hit.w == WF_MISS)
        return;
#if WF_HAS_SPHERE_LIGHTS
    if ((v.hit.w & WF_SPHERE_HIT) != 0u)
        return; // sphere lights are pure emitters: they absorb what reaches them
#endif
    vec3 toLight = -v.direction;
#if WF_HAS_INSTANCES
    float t = instancedHitDistance(v.hit.x, v.hit.w, uintBitsToFloat(v.hit.y),
                                   uintBitsToFloat(v.hit.z), v.origin);
#else
    float t = uintBitsToFloat(v.hit.x);
#endif
    // No ray cone on a light subpath: textures read their full-resolution level, as light
    // sampling's emission does.
    SurfaceHit surface = loadSurface(v.hit.x, v.hit.w, uintBitsToFloat(v.hit.y),
                                     uintBitsToFloat(v.hit.z), toLight, 0.0);
#if WF_HAS_VOLUME
    if (!surface.frontFace && surfaceTransmits(surface))
        v.beta *= exp(-surface.absorption * t); // as path_vertex.glsl: the same Beer-Lambert
#endif
    BsdfParams bsdf = bsdfAt(surface);
#if WF_BSDF_LAYERS
    BsdfLayers layers = layersAt(surface);
    bool hasNonDelta = layeredHasNonDelta(bsdf, layers);
#else
    bool hasNonDelta = bsdfHasNonDelta(bsdf);
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    VcmMisConfig cfg = bdptMisConfig(v.sampleIndex);
    float cosHit = abs(dot(toLight, surface.ng));
    VcmSubpathMis mis;
    if (v.depth == 0u) {
        mis = bdptLightAtFirstHit(cfg, v.mis, surface.p, v.direction, t, cosHit);
    } else {
        mis = bdptMis(v.mis);
        vcmOnHit(cfg, mis, t * t, cosHit);
    }
    // Kept for the camera subpath's connections (and merges) where one can still reach it.
    if (bdptKeepsLightVertex(v.depth)) {
        bdptStoreLightVertex(v.path, v.depth, v.hit, surface.p, toLight,
                             hasNonDelta ? v.beta : vec3(0.0), mis, v.sampleIndex);
        lightDepths[v.path] = v.depth + 1u;
    }
#endif
    // The path tracer's frame for this surface (shading_frame.glsl): an anisotropic BSDF
    // depends on its x axis.
    ShadingFrame frame = shadingFrameAt(surface);
    vec3 toLightLocal = toShadingFrame(frame, toLight);
#if WF_BSDF_LAYERS && WF_HAS_CLEARCOAT && WF_HAS_CLEARCOAT_NORMAL_MAPS
    placeCoatNormal(layers, surface, frame);
#endif

    // The connection to the camera makes a path of depth + 2 segments.
    CameraConnection c;
    if (hasNonDelta && v.depth + 2u <= params.maxDepth &&
        connectToCamera(surface.p,
                        lightVertexSample2D(v.pixel, v.sampleIndex, v.depth, WF_DIM_LIGHT_POINT),
                        c)) {
        vec3 toCameraLocal = toShadingFrame(frame, c.toCamera);
        // In the radiance order f(toCamera, toLight) is the path tracer's own BSDF (no
        // refraction factor); the shading-normal correction makes it f_s |toCamera.ng|.
#if WF_BSDF_LAYERS
        vec3 f = layeredEval(bsdf, layers, toCameraLocal, toLightLocal);
#else
        vec3 f = bsdfEval(bsdf, toCameraLocal, toLightLocal);
#endif
        vec3 value = v.beta * f *
                     (lightShareSplatScale() * abs(toCameraLocal.z) *
                      adjointShadingFactor(surface.ns, surface.ng, toLight, c.toCamera) *
                      c.importance);
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
        // The strategy t = 1 among all that make this path (vcm_mis.h).
#if WF_BSDF_LAYERS
        float reversePdf = layeredPdf(bsdf, layers, toCameraLocal, toLightLocal);
#else
        float reversePdf = bsdfPdf(bsdf, toCameraLocal, toLightLocal);
#endif
        float cameraPdfA = float(params.pixelCount) * c.directionPdf *
                           abs(dot(c.toCamera, surface.ng)) / c.dist2;
        value *= vcmWeightCameraConnect(cfg, mis, cameraPdfA, reversePdf);
#endif
        value = clampContribution(value);
        if (any(greaterThan(value, vec3(0.0))) || any(isnan(value))) {
            v.connects = true;
            v.splatOrigin =
                offsetRayOrigin(surface.p, surface.pError, frame.outside, c.toCamera);
            v.splatSegment = c.lensPoint - v.splatOrigin;
            v.splatPixel = c.pixel;
            v.splat = value;
        }
    }

    // The next vertex is worth finding only if it can still connect: depth + 3 segments.
    if (v.depth + 3u > params.maxDepth)
        return;
    BsdfSample s;
    float uLobe = lightVertexSample1D(v.pixel, v.sampleIndex, v.depth, WF_DIM_BSDF_LOBE);
    vec2 uDirection = lightVertexSample2D(v.pixel, v.sampleIndex, v.depth, WF_DIM_BSDF);
#if WF_BSDF_LAYERS
    if (!layeredSample(bsdf, layers, toLightLocal, uLobe, uDirection, s))
        return;
#else
    if (!bsdfSample(bsdf, toLightLocal, uLobe, uDirection, s))
        return;
#endif
    vec3 wi = fromShadingFrame(frame, s.wi);
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    float scatterReversePdf = s.pdf; // a Dirac bounce: the same lobe both ways
    if (!s.isDelta) {
#if WF_BSDF_LAYERS
        scatterReversePdf = layeredPdf(bsdf, layers, s.wi, toLightLocal);
#else
        scatterReversePdf = bsdfPdf(bsdf, s.wi, toLightLocal);
#endif
    }
    vcmOnScatter(cfg, mis, abs(dot(wi, surface.ng)), s.pdf, scatterReversePdf, s.isDelta);
    v.mis = bdptStored(mis);
#endif
    vec3 beta = v.beta * s.weight *
                adjointThroughputFactor(surface.ns, surface.ng, toLight, wi, s.eta);
    if (v.depth >= params.rrDepth) {
        // Relative to the emitted throughput, which carries the light's power (far above 1):
        // survival falls as the subpath loses what it started with, as a camera path's does.
        float survive = min(max(beta.r, max(beta.g, beta.b)) / v.betaStart, 1.0);
        beta = lightVertexSample1D(v.pixel, v.sampleIndex, v.depth, WF_DIM_ROULETTE) < survive
                   ? beta / survive
                   : vec3(0.0);
    }
    if (max(beta.r, max(beta.g, beta.b)) < params.minThroughput * v.betaStart)
        beta = vec3(0.0);
    v.continues = any(greaterThan(beta, vec3(0.0)));
    if (v.continues) {
        v.origin = offsetRayOrigin(surface.p, surface.pError, frame.outside, wi);
        v.direction = wi;
        v.beta = beta;
    }
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    bool inQueue = index < counters.rayArgs.count;
    uint path = inQueue ? rayQueueAt(pass.depth, index) : 0u;
    LightVertex v;
    v.continues = false;
    v.connects = false;
    if (inQueue) {
#if WF_MOTION
        wfRayTime = rayTime[path];
#endif
        v.pixel = wavePathPixel(pass, path);
        v.sampleIndex = wavePathSample(pass, path);
        v.depth = pass.depth;
        v.hit = hitAt(index);
        v.origin = rayOriginAt(path).xyz;
        v.direction = rayDirectionAt(path).xyz;
        vec4 pathThroughput = throughputAt(path);
        v.beta = pathThroughput.rgb;
        v.betaStart = pathThroughput.w;
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
        v.path = path;
        v.mis = pathMis[path];
#endif
        shadeLightVertex(v);
        if (v.continues) {
            rayOrigin[path] = wfPack(vec4(v.origin, 0.0));
            rayDirection[path] = wfPack(vec4(v.direction, 0.0));
            throughput[path] = wfPack(vec4(v.beta, v.betaStart));
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
            pathMis[path] = v.mis;
#endif
        }
    }

    // Appends happen in uniform control flow: every lane of the subgroup takes part.
    uint raySlot = appendRay(v.continues);
    if (v.continues)
        rayQueues[((pass.depth + 1u) & 1u) * params.pathCapacity + raySlot] = path;
    uint splatSlot = appendSplat(v.connects);
    if (v.connects) {
        // The light film entry: the pixel it lands in, in the sample slot of the subpath's own
        // sample index (waves of light tracing cover the whole image: accumulate.comp).
        uint entry = (v.sampleIndex - pass.sampleBase) * pass.wavePixels + v.splatPixel;
        shadowOrigin[splatSlot] = wfPack(uvec4(floatBitsToUint(v.splatOrigin), entry));
        shadowDirection[splatSlot] = wfPack(vec4(v.splatSegment, 0.0));
        // w: the subpath's time, at which light_splat tests the segment (WF_MOTION).
        shadowRadiance[splatSlot] = wfPack(vec4(v.splat, pathTime()));
    }
}
