// Ray queries against the whole scene (BVH of triangles plus the few sphere lights), shared by
// the intersect and shadow passes and by the megakernel baseline.
#define WF_BVH_PAIR(i) bvhPairAt(i)
#define WF_BVH_TRIANGLE(i) triangleAt(i)
#include "bvh_traverse.h"
#include "light_sampling.h"

// (t, b1, b2, triangle) as bits, (t, -, -, WF_SPHERE_HIT | light), or w = WF_MISS.
uvec4 intersectClosest(vec3 origin, vec3 direction) {
    HitRecord hit;
    uvec4 result = uvec4(0u, 0u, 0u, WF_MISS);
    float closest = 3.0e38;
    if (traceClosest(origin, direction, closest, hit)) {
        result = uvec4(floatBitsToUint(hit.t), floatBitsToUint(hit.b1), floatBitsToUint(hit.b2),
                       hit.triangle);
        closest = hit.t;
    }
#if WF_HAS_SPHERE_LIGHTS
    // Sphere lights are few: test them all rather than put them in the BVH.
    for (uint i = 0u; i < params.sphereLightCount; ++i) {
        PunctualLight sphere = lightAt(i);
        float t = raySphereNear(origin, direction, sphere.position, sphere.radius, false);
        if (t > 0.0 && t < closest) {
            closest = t;
            result = uvec4(floatBitsToUint(t), 0u, 0u, WF_SPHERE_HIT | i);
        }
    }
#endif
    return result;
}

// Whether anything but the light it ends on blocks the segment origin + t * segment, t in (0, 1).
// `target` is that light's emitter source (WF_EMITTER_* | index). The light itself cannot block
// it: a triangle is flat, and the segment reaches a sphere's near side from outside. Testing
// it anyway lets rounding decide: from far away the computed t of a sphere or a small triangle
// errs by more than the segment end's offset off its surface, and a share of the samples went
// dark (issue 13: sphere lights 20-30% low away from them).
bool segmentOccluded(vec3 origin, vec3 segment, uint target) {
    uint targetKind = target & WF_EMITTER_KIND_MASK;
    uint targetIndex = target & WF_EMITTER_INDEX_MASK;
    bool occluded = traceAny(origin, segment, 1.0,
                             targetKind == WF_EMITTER_TRIANGLE ? targetIndex : WF_NO_TRIANGLE);
#if WF_HAS_SPHERE_LIGHTS
    float length_ = length(segment);
    uint skipSphere = targetKind == WF_EMITTER_LIGHT ? targetIndex : ~0u;
    for (uint i = 0u; i < params.sphereLightCount && !occluded; ++i) {
        PunctualLight sphere = lightAt(i);
        float t = raySphereNear(origin, segment / length_, sphere.position, sphere.radius, false);
        occluded = i != skipSphere && t > 0.0 && t < length_;
    }
#endif
    return occluded;
}
