// BDPT's densities of emitter points (bidir/bdpt_state.glsl): what next-event estimation would
// have had for the point a light subpath left, computed at its first hit. Needs lights.glsl.
#ifndef WF_BDPT_EMITTERS_GLSL
#define WF_BDPT_EMITTERS_GLSL
#include "bidir/bdpt_state.glsl"

// What the density of next-event estimation choosing an emitter point is, in area measure
// seen from `receiver` (solid angle for infinite lights), and the light's kind: what
// vcmStartLight needs. For triangles and spheres it depends on the receiver (spherical
// triangles, cones), so a light subpath computes it at its first hit (a camera subpath that
// finds an emitter has it already: path_vertex.glsl's lightPdf). t: distance from receiver to
// the point; cosAtLight there.
struct EmitterDensity {
    float directPdfA;
    bool finite;
    bool dirac;
};

EmitterDensity emitterDensity(uint emitter, vec3 receiver, vec3 toLight, float t,
                              float cosAtLight) {
    EmitterDensity e;
    float pmf = emitterAt(emitter).pmf;
    e.directPdfA = pmf;
    e.finite = true;
    e.dirac = false;
    uint source = emitterAt(emitter).source;
    uint index = source & WF_EMITTER_INDEX_MASK;
    uint kind = source & WF_EMITTER_KIND_MASK;
#if WF_HAS_TRIANGLE_EMITTERS
    if (kind == WF_EMITTER_TRIANGLE)
        e.directPdfA = triangleLightPdf(pmf, triangleAt(index), receiver, t, cosAtLight) *
                       cosAtLight / (t * t);
#endif
#if WF_HAS_ENVIRONMENT
    if (kind == WF_EMITTER_ENVIRONMENT) {
        e.directPdfA = environmentLightPdf(toLight);
        e.finite = false;
    }
#endif
#if WF_HAS_LIGHTS
    if (kind == WF_EMITTER_LIGHT) {
        PunctualLight light = lightAt(index);
        if (light.type == WF_LIGHT_SPHERE) {
#if WF_HAS_SPHERE_LIGHTS
            e.directPdfA = sphereLightPdf(pmf, light, receiver, t, cosAtLight) * cosAtLight /
                           (t * t);
#endif
        } else {
            e.dirac = true;
            e.finite = light.type != WF_LIGHT_DIRECTIONAL;
        }
    }
#endif
    return e;
}

#ifdef WF_LIGHT_SUBPATH_GLSL
void bdptStartLightSubpath(uint path, EmittedRay ray) {
    pathMis[path] = vec4(ray.emissionPdfW, ray.cosAtLight, 0.0, uintBitsToFloat(ray.emitter));
}
#endif

// The light subpath's quantities at its first hit (x1 at distance t, cosHit to its geometric
// normal), from what light_raygen kept.
VcmSubpathMis bdptLightAtFirstHit(VcmMisConfig cfg, vec4 start, vec3 x1, vec3 direction, float t,
                                  float cosHit) {
    EmitterDensity e = emitterDensity(floatBitsToUint(start.w), x1, -direction, t, start.y);
    VcmSubpathMis mis = vcmStartLight(cfg, e.directPdfA, start.x, start.y, e.finite, e.dirac);
    // Rays from the disk of an infinite light: its pdf is already per unit area.
    vcmOnHit(cfg, mis, e.finite ? t * t : 1.0, cosHit);
    return mis;
}

#endif
