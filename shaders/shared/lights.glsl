// Emissive-triangle sampling for next-event estimation: an emitter chosen by power through the
// alias table, a point uniform in its area, the pdf converted to solid angle at the shading
// point. emitterSolidAnglePdf gives the same density for a BSDF-sampled ray that hits the
// emitter, so MIS weights on both sides agree.
#if WF_HAS_EMITTERS

struct LightSample {
    vec3 direction;   // unit, from the shading point to the light point
    float pdf;        // solid-angle density, emitter choice included; 0 if unusable
    vec3 emission;
    vec3 offsetPoint; // light point pushed off the light toward the shading point
};

float emitterSolidAnglePdf(uint emitter, float area, float distance, float cosLight) {
    if (area <= 0.0 || cosLight <= 0.0)
        return 0.0;
    return emitters[emitter].pmf * distance * distance / (area * cosLight);
}

uint chooseEmitter(float u) {
    float scaled = u * float(params.emitterCount);
    uint slot = min(uint(scaled), params.emitterCount - 1u);
    return (scaled - float(slot)) < emitters[slot].aliasProb ? slot : emitters[slot].alias;
}

LightSample sampleEmitter(float uChoice, vec2 uPoint, vec3 p) {
    LightSample result;
    result.pdf = 0.0;
    result.direction = vec3(0.0, 0.0, 1.0);
    result.emission = vec3(0.0);
    result.offsetPoint = p;

    uint emitter = chooseEmitter(uChoice);
    Triangle tri = triangles[emitters[emitter].triangle];
    Material material = materials[tri.material];
    vec2 b = sampleUniformTriangle(uPoint);
    vec3 q = triangleHitPoint(tri.p0, tri.p1, tri.p2, b.x, b.y);
    vec3 toLight = q - p;
    float distance = length(toLight);
    if (!(distance > 0.0))
        return result;
    vec3 direction = toLight / distance;
    vec3 cross12 = cross(tri.p1 - tri.p0, tri.p2 - tri.p0);
    vec3 nl = normalize(cross12);
    float cosLight = dot(nl, -direction);
    bool doubleSided = (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u;
    if (cosLight < 0.0 && doubleSided) {
        nl = -nl;
        cosLight = -cosLight;
    }
    result.pdf = emitterSolidAnglePdf(emitter, 0.5 * length(cross12), distance, cosLight);
    result.direction = direction;
    result.emission = material.emission;
    vec3 qError = triangleSpawnError(tri.p0, tri.p1, tri.p2, b.x, b.y);
    result.offsetPoint = offsetRayOrigin(q, qError, nl, -direction);
    return result;
}

#endif
