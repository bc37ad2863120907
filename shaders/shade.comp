#version 460
// shade: one path vertex per ray in the current queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), hits, path state, scene, lights.
// Out: radiance += emission found by the ray (MIS-weighted against light sampling); appends
// the path to shadowQueue with a next-event connection (shadowOrigin/Direction/Radiance) and
// to rayQueue[(depth + 1) & 1] with a BSDF-sampled continuation (after Russian roulette).
// Estimator: WF_LIGHT_SAMPLING 0 = BSDF sampling only, 1 = NEE only, 2 = MIS (power heuristic).
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"
#include "queue_append.glsl"
#include "geometry.h"
#include "rng.h"
#include "sampling.h"
#include "light_sampling.h"
#include "bsdf.h"
#include "lights.glsl"
#include "surface.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

WF_DEFINE_QUEUE_APPEND(appendRay, counters.rayCount)
#if WF_HAS_EMITTERS
WF_DEFINE_QUEUE_APPEND(appendShadow, counters.shadowCount)
#endif

// Weight of emission found by a ray whose direction had BSDF density directionPdf (0: camera or
// a specular bounce, which light sampling cannot reproduce) and light density lightPdf.
float emissionWeight(float directionPdf, float lightPdf) {
#if WF_LIGHT_SAMPLING == 0
    return 1.0;
#elif WF_LIGHT_SAMPLING == 1
    return directionPdf == 0.0 || lightPdf == 0.0 ? 1.0 : 0.0;
#else
    return directionPdf == 0.0 ? 1.0 : powerHeuristic(directionPdf, lightPdf);
#endif
}

// --clamp: scale a contribution down so no channel exceeds the limit (biased, off by default).
vec3 clampContribution(vec3 c) {
    float peak = max(c.r, max(c.g, c.b));
    return params.clampRadiance > 0.0 && peak > params.clampRadiance
               ? c * (params.clampRadiance / peak) : c;
}

void addRadiance(uint path, vec3 contribution) {
    radiance[path].rgb += clampContribution(contribution);
}

void main() {
    uint index = gl_GlobalInvocationID.x;
    bool inQueue = index < counters.rayArgs.count;
    uint path = inQueue ? rayQueues[(pass.depth & 1u) * params.pathCapacity + index] : 0u;
    uvec4 hit = inQueue ? hits[path] : uvec4(0u, 0u, 0u, WF_MISS);
    bool continues = false;
    bool connects = false;
    vec3 direction = rayDirection[path].xyz;
    vec3 origin = rayOrigin[path].xyz;
    float previousPdf = rayOrigin[path].w; // BSDF density of this ray's direction
    vec3 beta = throughput[path].rgb;
    // Product of eta^2 over refractions: radiance scaling across interfaces must not steer
    // Russian roulette (pbrt's etaScale).
    float etaScale = throughput[path].w;
    float t = uintBitsToFloat(hit.x);

#if WF_HAS_ENVIRONMENT
    if (inQueue && hit.w == WF_MISS) {
        float lightPdf = 0.0;
#if WF_HAS_EMITTERS && WF_LIGHT_SAMPLING != 0
        lightPdf = environmentLightPdf(direction);
#endif
        addRadiance(path, beta * environmentRadiance(direction) * emissionWeight(previousPdf, lightPdf));
    }
#endif
#if WF_HAS_SPHERE_LIGHTS
    // Sphere lights are pure emitters: add what leaves the outside and end the path.
    if (inQueue && hit.w != WF_MISS && (hit.w & WF_SPHERE_HIT) != 0u) {
        PunctualLight light = lights[hit.w & ~WF_SPHERE_HIT];
        vec3 normal = normalize(origin + t * direction - light.position);
        float cosLight = dot(normal, -direction);
        if (cosLight > 0.0) {
            float lightPdf = 0.0;
#if WF_HAS_EMITTERS && WF_LIGHT_SAMPLING != 0
            if (light.emitter != WF_NO_EMITTER)
                lightPdf = sphereLightPdf(light.emitter, light, origin, t, cosLight);
#endif
            addRadiance(path, beta * sphereRadiance(light) * emissionWeight(previousPdf, lightPdf));
        }
        hit.w = WF_MISS;
    }
#endif

    if (hit.w != WF_MISS) {
        uint pixel = path % params.pixelCount;
        uint sampleIndex = pass.sampleBase + path / params.pixelCount;
        vec3 wo = -direction;
        SurfaceHit surface =
            loadSurface(hit.w, uintBitsToFloat(hit.y), uintBitsToFloat(hit.z), wo);

        if (any(greaterThan(surface.emission, vec3(0.0)))) {
            float lightPdf = 0.0;
#if WF_HAS_TRIANGLE_EMITTERS && WF_LIGHT_SAMPLING != 0
            if (previousPdf > 0.0 && surface.emitter != WF_NO_EMITTER)
                lightPdf = triangleLightPdf(surface.emitter, triangles[hit.w], origin, t,
                                            abs(dot(surface.ng, wo)));
#endif
            addRadiance(path, beta * surface.emission * emissionWeight(previousPdf, lightPdf));
        }

        BsdfParams bsdf;
        bsdf.baseColor = surface.baseColor;
        bsdf.metallic = surface.metallic;
        bsdf.roughness = surface.roughness;
        bsdf.ior = surface.ior;
        bsdf.transmission = surface.transmission;
        bsdf.specular = surface.specular;
        bsdf.specularColor = surface.specularColor;
        // Opaque surfaces shade two-sided (the frame faces the arriving ray); transmissive
        // ones keep +z on the outside so that the BSDF knows which medium the ray is in.
        vec3 n = surface.transmission > 0.0 && !surface.frontFace ? -surface.ns : surface.ns;
        vec3 tangent, bitangent;
        buildOrthonormalBasis(n, tangent, bitangent);
        vec3 woLocal = vec3(dot(wo, tangent), dot(wo, bitangent), dot(wo, n));
        vec3 geometricOutside = surface.transmission > 0.0 && !surface.frontFace ? -surface.ng
                                                                                 : surface.ng;

#if WF_HAS_EMITTERS && WF_LIGHT_SAMPLING != 0
        // Next-event estimation: the connection adds one more path segment.
        if (pass.depth + 2u <= params.maxDepth && bsdfHasNonDelta(bsdf)) {
            LightSample light = sampleLight(
                sample1D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_LIGHT_CHOICE),
                         params.seed),
                sample2D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_LIGHT_POINT),
                         params.seed),
                sample1D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_LIGHT_EXTRA),
                         params.seed),
                surface.p);
            vec3 wiLocal = vec3(dot(light.direction, tangent), dot(light.direction, bitangent),
                                dot(light.direction, n));
            if (light.pdf > 0.0) {
                vec3 f = bsdfEval(bsdf, woLocal, wiLocal);
                float weight = 1.0;
#if WF_LIGHT_SAMPLING == 2
                if (!light.isDelta)
                    weight = powerHeuristic(light.pdf, bsdfPdf(bsdf, woLocal, wiLocal));
#endif
                vec3 contribution =
                    beta * f * light.radiance * (abs(wiLocal.z) * weight / light.pdf);
                vec3 from = offsetRayOrigin(surface.p, surface.pError, geometricOutside,
                                            light.direction);
                shadowOrigin[path] = vec4(from, 0.0);
                shadowDirection[path] = vec4(light.segmentEnd - from, 0.0);
                shadowRadiance[path] = vec4(clampContribution(contribution), 0.0);
                connects = any(greaterThan(contribution, vec3(0.0)));
            }
        }
#endif

        if (pass.depth + 1u < params.maxDepth) {
            BsdfSample s;
            bool sampled = bsdfSample(
                bsdf, woLocal,
                sample1D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_BSDF_LOBE),
                         params.seed),
                sample2D(pixel, sampleIndex, bounceDimension(pass.depth, WF_DIM_BSDF),
                         params.seed),
                s);
            if (sampled) {
                vec3 wi = normalize(tangent * s.wi.x + bitangent * s.wi.y + n * s.wi.z);
                beta *= s.weight;
                etaScale *= s.eta * s.eta;
                if (pass.depth >= params.rrDepth) {
                    // Survive with the throughput's largest channel (at most 1) and divide by
                    // it: unbiased, and paths that carry little end early.
                    float survive = min(max(beta.r, max(beta.g, beta.b)) * etaScale, 1.0);
                    float u = sample1D(pixel, sampleIndex,
                                       bounceDimension(pass.depth, WF_DIM_ROULETTE), params.seed);
                    beta = u < survive ? beta / survive : vec3(0.0);
                }
                // --min-throughput: the course's biased alternative to roulette.
                if (max(beta.r, max(beta.g, beta.b)) < params.minThroughput)
                    beta = vec3(0.0);
                continues = any(greaterThan(beta, vec3(0.0)));
                if (continues) {
                    vec3 next = offsetRayOrigin(surface.p, surface.pError, geometricOutside, wi);
                    // A Dirac bounce stores pdf 0: emission it finds counts in full.
                    rayOrigin[path] = vec4(next, s.isDelta ? 0.0 : s.pdf);
                    rayDirection[path] = vec4(wi, 0.0);
                    throughput[path] = vec4(beta, etaScale);
                }
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
