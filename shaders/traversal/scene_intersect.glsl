// Ray queries against the whole scene (BVH of triangles plus the few sphere lights), shared by
// the intersect and shadow passes and by the megakernel baseline.
#define WF_BVH_PAIR(i) bvhPairAt(i)
#define WF_BVH_TRIANGLE(i) triangleAt(i)
#define WF_BVH_INSTANCE(i) instanceAt(i)
#include "traversal/bvh_traverse.h"
#include "lights/light_sampling.h"

// (t, b1, b2, triangle) as bits, (t, -, -, WF_SPHERE_HIT | light), or w = WF_MISS. In
// two-level scenes a triangle hit's x holds its instance instead of t (hitDistance).
uvec4 intersectClosest(vec3 origin, vec3 direction) {
    HitRecord hit;
    uvec4 result = uvec4(0u, 0u, 0u, WF_MISS);
    float closest = 3.0e38;
#if WF_HAS_INSTANCES
    uint instance;
    if (traceClosestInstanced(origin, direction, closest, hit, instance)) {
        result = uvec4(instance, floatBitsToUint(hit.b1), floatBitsToUint(hit.b2), hit.triangle);
        closest = hit.t;
    }
#else
    if (traceClosest(origin, direction, closest, hit)) {
        result = uvec4(floatBitsToUint(hit.t), floatBitsToUint(hit.b1), floatBitsToUint(hit.b2),
                       hit.triangle);
        closest = hit.t;
    }
#endif
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

// Whether anything blocks the segment origin + t * segment, t in (0, 1), that ends on sphere
// light `targetSphere` (or WF_NO_SPHERE). That sphere cannot block it, since the segment
// reaches its near side from outside; testing it anyway let rounding decide, and from far away
// the computed t errs by more than the segment end's offset off the sphere, so 20-30% of the
// samples went dark (issue 13). Triangles keep the plain test: their ends are offset by the
// intersector's own error bound.
bool segmentOccluded(vec3 origin, vec3 segment, uint targetSphere) {
#if WF_HAS_INSTANCES
    bool occluded = traceAnyInstanced(origin, segment, 1.0);
#else
    bool occluded = traceAny(origin, segment, 1.0);
#endif
#if WF_HAS_SPHERE_LIGHTS
    float length_ = length(segment);
    for (uint i = 0u; i < params.sphereLightCount && !occluded; ++i) {
        PunctualLight sphere = lightAt(i);
        float t = raySphereNear(origin, segment / length_, sphere.position, sphere.radius, false);
        occluded = i != targetSphere && t > 0.0 && t < length_;
    }
#endif
    return occluded;
}
