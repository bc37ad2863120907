// Next-event estimation over the light table (emissive triangles, sphere lights, Dirac point,
// spot and directional lights, the environment) and the matching densities for rays that hit
// a light by BSDF sampling, so that MIS weights on both sides agree.
// Variant switches: WF_TRIANGLE_SOLID_ANGLE (spherical-triangle sampling, else area),
// WF_SPHERE_SOLID_ANGLE (cone sampling, else area). Needs surface.glsl (surfaceEmission).

#if WF_HAS_ENVIRONMENT
uint environmentTexel(vec3 direction) {
    vec2 uv = directionToEquirect(direction);
    uvec2 texel = min(uvec2(uv * vec2(params.environmentWidth, params.environmentHeight)),
                      uvec2(params.environmentWidth - 1u, params.environmentHeight - 1u));
    return texel.y * params.environmentWidth + texel.x;
}

vec3 environmentRadiance(vec3 direction) { return environmentAt(environmentTexel(direction)); }
#endif

#if WF_HAS_LIGHTS
vec3 sphereRadiance(PunctualLight light) {
    return light.intensity / (WF_PI * light.radius * light.radius);
}
#endif

#if WF_HAS_EMITTERS

struct LightSample {
    vec3 direction;  // unit, from the shading point towards the light
    float pdf;       // solid-angle density with the light choice; for Dirac lights the choice only
    vec3 radiance;   // incident radiance (Dirac lights: irradiance at normal incidence)
    vec3 segmentEnd; // where the shadow ray stops: just off the light, or outside the scene
    uint sphere;     // the sphere light it ends on, left out of the shadow test, or WF_NO_SPHERE
    bool isDelta;
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    // What BDPT's MIS weight of the connection needs (bidir/vcm_mis.h, vcmWeightNee): the
    // density of a light subpath emitting this point and direction (pick included), the
    // cosine at the light point (1 for points and infinite lights), and the connection's
    // solid-angle density for the weight (pdf, but pick x distance^2 for a point or spot
    // light, whose position is a Dirac in area measure).
    float emissionPdfW;
    float cosAtLight;
    float misPdfW;
#endif
};

// Sets the BDPT fields of s (nothing without BDPT).
void setEmissionDensity(inout LightSample s, float emissionPdfW, float cosAtLight,
                        float misPdfW) {
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    s.emissionPdfW = emissionPdfW;
    s.cosAtLight = cosAtLight;
    s.misPdfW = misPdfW;
#endif
}

uint chooseEmitter(float u) {
    float scaled = u * float(params.emitterCount);
    uint slot = min(uint(scaled), params.emitterCount - 1u);
    return (scaled - float(slot)) < emitterAt(slot).aliasProb ? slot : emitterAt(slot).alias;
}

#if WF_LIGHT_TREE
#define WF_LIGHT_TREE_NODE(i) lightTreeNodeAt(i)
#include "lights/light_tree.h"
#endif

// The emitter next-event estimation connects p to, and the probability of choosing it there:
// from the alias table, and with --light-selection tree through the tree's slot (the last)
// down the tree with uTree, weighing the side `receiver` (encodeReceiverNormal) faces.
// WF_LIGHT_TREE_LEAF with pmf 0 when no light can be chosen.
uint chooseLight(float uChoice, float uTree, vec3 p, float receiver, out float pmf) {
    uint slot = chooseEmitter(uChoice);
    pmf = emitterAt(slot).pmf;
#if WF_LIGHT_TREE
    if (slot == params.emitterCount - 1u) {
        float treePmf;
        uint emitter = lightTreeSample(p, decodeReceiverNormal(receiver), uTree, treePmf);
        pmf *= treePmf;
        return emitter;
    }
#endif
    return slot;
}

// The probability that chooseLight picks `emitter` at p: what MIS needs when a BSDF-sampled
// ray from p finds that light.
float lightPmf(uint emitter, vec3 p, float receiver) {
#if WF_LIGHT_TREE
    uvec4 trail = lightTreeTrailAt(emitter);
    if (trail.z != 0u)
        return emitterAt(params.emitterCount - 1u).pmf *
               lightTreePmf(p, decodeReceiverNormal(receiver), trail.xy);
#endif
    return emitterAt(emitter).pmf;
}

LightSample noLight(vec3 p) {
    LightSample s;
    s.direction = vec3(0.0, 0.0, 1.0);
    s.pdf = 0.0;
    s.radiance = vec3(0.0);
    s.segmentEnd = p;
    s.sphere = WF_NO_SPHERE;
    s.isDelta = false;
    setEmissionDensity(s, 0.0, 1.0, 0.0);
    return s;
}

// A point far enough along `direction` to leave the scene's bounding sphere from p.
vec3 pointOutsideScene(vec3 p, vec3 direction) {
    return p + direction * (2.0 * (params.sceneRadius + length(p - params.sceneCenter)));
}

#if WF_HAS_TRIANGLE_EMITTERS
// Density of reaching triangle `tri` from `from` along a direction hitting it at distance t,
// chosen with probability pmf.
float triangleLightPdf(float pmf, Triangle tri, vec3 from, float t, float cosLight) {
#if WF_TRIANGLE_SOLID_ANGLE
    float omega = triangleSolidAngle(from, tri.p0, tri.p1, tri.p2);
    if (useSphericalTriangleSampling(omega))
        return pmf / omega;
#endif
    float area = 0.5 * length(cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
    return area > 0.0 && cosLight > 0.0 ? pmf * t * t / (area * cosLight) : 0.0;
}

// The density of a light subpath leaving the triangle at a point, at cosLight to its normal:
// pick x 1 / area x cos / pi, halved for a double-sided emitter (light_emission.h's
// emitTriangle).
float triangleEmissionPdfW(float pmf, Triangle tri, Material material, float cosLight) {
    float area = 0.5 * length(cross(tri.p1 - tri.p0, tri.p2 - tri.p0));
    float sides = (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u ? 0.5 : 1.0;
    return area > 0.0 ? pmf * sides * abs(cosLight) * WF_INV_PI / area : 0.0;
}

// Barycentrics (b1, b2) of a point in the triangle's plane, clamped into the triangle.
vec2 planeBarycentrics(Triangle tri, vec3 q) {
    vec3 e1 = tri.p1 - tri.p0, e2 = tri.p2 - tri.p0, v = q - tri.p0;
    float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    float d20 = dot(v, e1), d21 = dot(v, e2);
    float denominator = d00 * d11 - d01 * d01;
    vec2 b = denominator > 0.0 ? vec2(d11 * d20 - d01 * d21, d00 * d21 - d01 * d20) / denominator
                               : vec2(0.0);
    b = max(b, vec2(0.0));
    return b / max(1.0, b.x + b.y);
}

LightSample sampleTriangleLight(float pmf, uint triangleIndex, vec2 u, vec3 p) {
    Triangle tri = triangleAt(triangleIndex);
    Material material = materialAt(tri.material);
    vec3 cross12 = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    vec3 nl = normalize(cross12);
    vec2 b = sampleUniformTriangle(u);
    bool solidAngle = false;
    float omega = 0.0;
#if WF_TRIANGLE_SOLID_ANGLE
    omega = triangleSolidAngle(p, tri.p0, tri.p1, tri.p2);
    if (useSphericalTriangleSampling(omega)) {
        vec3 direction = sampleSphericalTriangle(normalize(tri.p0 - p), normalize(tri.p1 - p),
                                                 normalize(tri.p2 - p), omega, u);
        float denominator = dot(direction, nl);
        if (denominator == 0.0 || dot(direction, direction) == 0.0)
            return noLight(p);
        float t = dot(tri.p0 - p, nl) / denominator;
        if (!(t > 0.0))
            return noLight(p);
        b = planeBarycentrics(tri, p + t * direction);
        solidAngle = true;
    }
#endif
    vec3 q = triangleHitPoint(tri.p0, tri.p1, tri.p2, b.x, b.y);
    vec3 toLight = q - p;
    float distance = length(toLight);
    if (!(distance > 0.0))
        return noLight(p);
    vec3 direction = toLight / distance;
    float cosLight = dot(nl, -direction);
    if (cosLight < 0.0 && (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u) {
        nl = -nl;
        cosLight = -cosLight;
    }
    if (!(cosLight > 0.0))
        return noLight(p); // the back of a one-sided emitter: no light this way
    LightSample s;
    s.direction = direction;
    s.pdf = solidAngle ? pmf / omega : triangleLightPdf(pmf, tri, p, distance, cosLight);
    s.radiance = surfaceEmission(triangleIndex, material, b.x, b.y); // textured emission too
    vec3 qError = triangleSpawnError(tri.p0, tri.p1, tri.p2, b.x, b.y);
    s.segmentEnd = offsetRayOrigin(q, qError, nl, -direction);
    s.sphere = WF_NO_SPHERE;
    s.isDelta = false;
    setEmissionDensity(s, triangleEmissionPdfW(pmf, tri, material, cosLight), cosLight, s.pdf);
    return s;
}
#endif

#if WF_HAS_SPHERE_LIGHTS
bool sphereUsesCone(PunctualLight light, vec3 from) {
#if WF_SPHERE_SOLID_ANGLE
    return length(light.position - from) > light.radius;
#else
    return false;
#endif
}

float sphereLightPdf(float pmf, PunctualLight light, vec3 from, float t, float cosLight) {
    if (sphereUsesCone(light, from))
        return pmf / (2.0 * WF_PI *
                      sphereConeOneMinusCos(light.radius, length(light.position - from)));
    float area = 4.0 * WF_PI * light.radius * light.radius;
    return cosLight > 0.0 ? pmf * t * t / (area * cosLight) : 0.0;
}

// The density of a light subpath leaving the sphere at a point, at cosLight to its normal
// (light_emission.h's emitSphere): pick x 1 / (4 pi R^2) x cos / pi.
float sphereEmissionPdfW(float pmf, PunctualLight light, float cosLight) {
    float area = 4.0 * WF_PI * light.radius * light.radius;
    return area > 0.0 ? pmf * abs(cosLight) * WF_INV_PI / area : 0.0;
}

// Error bound of a point computed as centre + radius * unit normal.
vec3 spherePointError(PunctualLight light) {
    return (abs(light.position) + vec3(light.radius)) * WF_GAMMA(6.0);
}

LightSample sampleSphereLight(float pmf, uint lightIndex, PunctualLight light, vec2 u, vec3 p) {
    vec3 q;
    if (sphereUsesCone(light, p)) {
        vec3 toCenter = light.position - p;
        float d = length(toCenter);
        vec3 direction = sampleCone(toCenter / d, sphereConeOneMinusCos(light.radius, d), u);
        q = p + direction * raySphereNear(p, direction, light.position, light.radius, true);
    } else {
        q = light.position + light.radius * sampleUniformSphere(u);
    }
    vec3 toLight = q - p;
    float distance = length(toLight);
    if (!(distance > 0.0))
        return noLight(p);
    LightSample s;
    s.direction = toLight / distance;
    vec3 nl = normalize(q - light.position);
    float cosLight = dot(nl, -s.direction);
    if (!(cosLight > 0.0))
        return noLight(p); // the far side of the sphere faces away
    s.pdf = sphereLightPdf(pmf, light, p, distance, cosLight);
    s.radiance = sphereRadiance(light);
    s.segmentEnd = offsetRayOrigin(q, spherePointError(light), nl, nl);
    s.sphere = lightIndex;
    s.isDelta = false;
    setEmissionDensity(s, sphereEmissionPdfW(pmf, light, cosLight), cosLight, s.pdf);
    return s;
}
#endif

#if WF_HAS_DELTA_LIGHTS
LightSample sampleDeltaLight(float pmf, PunctualLight light, vec3 p) {
    LightSample s;
    s.pdf = pmf;
    s.sphere = WF_NO_SPHERE;
    s.isDelta = true;
    if (light.type == WF_LIGHT_DIRECTIONAL) {
        s.direction = -light.direction;
        s.radiance = light.intensity; // lux: irradiance at normal incidence
        s.segmentEnd = pointOutsideScene(p, s.direction);
        // emitDirectional: the disk's density, the direction a Dirac.
        setEmissionDensity(s, pmf / (WF_PI * params.sceneRadius * params.sceneRadius), 1.0,
                           pmf);
        return s;
    }
    vec3 toLight = light.position - p;
    float distance2 = dot(toLight, toLight);
    if (!(distance2 > 0.0))
        return noLight(p);
    s.direction = toLight * inversesqrt(distance2);
    s.radiance = light.intensity / distance2; // candela / m^2 = irradiance
    if (light.type == WF_LIGHT_SPOT) {
        // glTF's recommended smooth falloff between the outer and inner cone.
        float cosAngle = dot(-s.direction, light.direction);
        float x = clamp((cosAngle - light.cosOuter) / max(light.cosInner - light.cosOuter, 1e-4),
                        0.0, 1.0);
        s.radiance *= x * x;
    }
    s.segmentEnd = light.position;
    // emitPoint and emitSpot: directions uniform over the sphere or the outer cone.
    float directionPdf = light.type == WF_LIGHT_SPOT
                             ? 1.0 / (2.0 * WF_PI * max(1.0 - light.cosOuter, 1e-30))
                             : 0.25 * WF_INV_PI;
    setEmissionDensity(s, pmf * directionPdf, 1.0, pmf * distance2);
    return s;
}
#endif

#if WF_HAS_ENVIRONMENT
float environmentLightPdf(vec3 direction) {
    uint texel = environmentTexel(direction);
    float pdfUV = environmentAliasAt(texel).pmf *
                  float(params.environmentWidth * params.environmentHeight);
    return emitterAt(params.environmentEmitter).pmf * equirectSolidAnglePdf(pdfUV, direction);
}

LightSample sampleEnvironment(float uTexel, vec2 u, vec3 p) {
    uint count = params.environmentWidth * params.environmentHeight;
    float scaled = uTexel * float(count);
    uint slot = min(uint(scaled), count - 1u);
    uint texel = (scaled - float(slot)) < environmentAliasAt(slot).aliasProb
                     ? slot : environmentAliasAt(slot).alias;
    uvec2 xy = uvec2(texel % params.environmentWidth, texel / params.environmentWidth);
    vec2 uv = (vec2(xy) + u) / vec2(params.environmentWidth, params.environmentHeight);
    LightSample s;
    s.direction = equirectToDirection(uv);
    s.pdf = environmentLightPdf(s.direction);
    s.radiance = environmentAt(texel);
    s.segmentEnd = pointOutsideScene(p, s.direction);
    s.sphere = WF_NO_SPHERE;
    s.isDelta = false;
    // emitEnvironment: the direction's density (pick included) x the disk's.
    setEmissionDensity(s, s.pdf / (WF_PI * params.sceneRadius * params.sceneRadius), 1.0, s.pdf);
    return s.pdf > 0.0 ? s : noLight(p);
}
#endif

LightSample sampleLight(float uChoice, vec2 uPoint, float uExtra, vec3 p, float receiver) {
    float pmf;
    uint emitter = chooseLight(uChoice, uExtra, p, receiver, pmf);
    if (!(pmf > 0.0))
        return noLight(p);
    uint source = emitterAt(emitter).source;
    uint index = source & WF_EMITTER_INDEX_MASK;
    uint kind = source & WF_EMITTER_KIND_MASK;
#if WF_HAS_TRIANGLE_EMITTERS
    if (kind == WF_EMITTER_TRIANGLE)
        return sampleTriangleLight(pmf, index, uPoint, p);
#endif
#if WF_HAS_ENVIRONMENT
    if (kind == WF_EMITTER_ENVIRONMENT)
        return sampleEnvironment(uExtra, uPoint, p);
#endif
#if WF_HAS_LIGHTS
    if (kind == WF_EMITTER_LIGHT) {
        PunctualLight light = lightAt(index);
#if WF_HAS_SPHERE_LIGHTS
        if (light.type == WF_LIGHT_SPHERE)
            return sampleSphereLight(pmf, index, light, uPoint, p);
#endif
#if WF_HAS_DELTA_LIGHTS
        return sampleDeltaLight(pmf, light, p);
#endif
    }
#endif
    return noLight(p);
}

#endif
