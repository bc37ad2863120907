#version 460
// shade: one path vertex per ray in the current queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), hits, path state, scene.
// Out: radiance += MIS-weighted emission; appends the path to shadowQueue with an NEE
// connection (shadowOrigin/Direction/Radiance) and to rayQueue[(depth + 1) & 1] with a
// cosine-sampled continuation (rayOrigin/Direction, throughput after Russian roulette).
// Lambertian surfaces, shaded two-sided; emission leaves front faces unless double-sided.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"
#include "queue_append.glsl"
#include "geometry.h"
#include "rng.h"
#include "sampling.h"
#include "lights.glsl"
#include "surface.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

WF_DEFINE_QUEUE_APPEND(appendRay, counters.rayCount)
#if WF_HAS_EMITTERS
WF_DEFINE_QUEUE_APPEND(appendShadow, counters.shadowCount)
#endif

void main() {
    uint index = gl_GlobalInvocationID.x;
    bool inQueue = index < counters.rayArgs.count;
    uint path = inQueue ? rayQueues[(pass.depth & 1u) * params.pathCapacity + index] : 0u;
    uvec4 hit = inQueue ? hits[path] : uvec4(0u, 0u, 0u, WF_MISS);
    bool continues = false;
    bool connects = false;

    if (hit.w != WF_MISS) {
        uint pixel = path % params.pixelCount;
        uint sampleIndex = pass.sampleBase + path / params.pixelCount;
        vec3 wo = -rayDirection[path].xyz;
        vec3 beta = throughput[path].rgb;
        float t = uintBitsToFloat(hit.x);
        SurfaceHit surface = loadSurface(hit.w, uintBitsToFloat(hit.y), uintBitsToFloat(hit.z), wo);

        if (any(greaterThan(surface.emission, vec3(0.0)))) {
            // rayOrigin.w is the BSDF pdf of the sampled direction; 0 means the vertex had no
            // light sampling (camera ray), so emission counts in full.
            float bsdfPdf = rayOrigin[path].w;
            float weight = 1.0;
#if WF_HAS_EMITTERS
            if (bsdfPdf > 0.0 && surface.emitter != WF_NO_EMITTER) {
                float lightPdf = emitterSolidAnglePdf(surface.emitter, surface.area, t,
                                                      abs(dot(surface.ng, wo)));
                weight = powerHeuristic(bsdfPdf, lightPdf);
            }
#endif
            radiance[path].rgb += beta * surface.emission * weight;
        }

        vec3 p = surface.p;
        vec3 pError = surface.pError;
        vec3 n = surface.ns;
        vec3 albedo = surface.baseColor;
        vec3 tangent, bitangent;
        buildOrthonormalBasis(n, tangent, bitangent);

#if WF_HAS_EMITTERS
        // Next-event estimation: a segment to a light point adds one more path segment.
        if (pass.depth + 2u <= params.maxDepth) {
            LightSample light = sampleEmitter(
                sample1D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_LIGHT_CHOICE),
                         params.seed),
                sample2D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_LIGHT_POINT),
                         params.seed),
                p);
            float cosSurface = dot(n, light.direction);
            if (light.pdf > 0.0 && cosSurface > 0.0) {
                float bsdfPdf = cosineHemispherePdf(cosSurface);
                float weight = powerHeuristic(light.pdf, bsdfPdf);
                vec3 contribution =
                    beta * albedo * WF_INV_PI * light.emission * (cosSurface * weight / light.pdf);
                vec3 from = offsetRayOrigin(p, pError, n, light.direction);
                shadowOrigin[path] = vec4(from, 0.0);
                shadowDirection[path] = vec4(light.offsetPoint - from, 0.0);
                shadowRadiance[path] = vec4(contribution, 0.0);
                connects = any(greaterThan(contribution, vec3(0.0)));
            }
        }
#endif

        // Continuation by cosine-weighted sampling: f * cos / pdf = albedo.
        if (pass.depth + 1u < params.maxDepth) {
            vec3 local = sampleCosineHemisphere(
                sample2D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_BSDF), params.seed));
            vec3 wi = normalize(tangent * local.x + bitangent * local.y + n * local.z);
            float pdf = cosineHemispherePdf(local.z);
            beta *= albedo;
            if (pass.depth + 1u >= params.rrDepth) {
                // Survive with the throughput's largest component (at most 1), then divide by
                // it: unbiased, and paths that carry little are cut early.
                float survive = min(max(beta.r, max(beta.g, beta.b)), 1.0);
                float u = sample1D(pixel, sampleIndex,
                                   bounceDimension(pass.depth, WF_DIM_ROULETTE), params.seed);
                beta = u < survive ? beta / survive : vec3(0.0);
            }
            continues = pdf > 0.0 && any(greaterThan(beta, vec3(0.0)));
            if (continues) {
                rayOrigin[path] = vec4(offsetRayOrigin(p, pError, n, wi), pdf);
                rayDirection[path] = vec4(wi, 0.0);
                throughput[path] = vec4(beta, 0.0);
            }
        }
    }

    uint raySlot = appendRay(continues);
    if (continues)
        rayQueues[((pass.depth + 1u) & 1u) * params.pathCapacity + raySlot] = path;
#if WF_HAS_EMITTERS
    uint shadowSlot = appendShadow(connects);
    if (connects)
        shadowQueue[shadowSlot] = path;
#endif
}
