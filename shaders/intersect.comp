#version 460
// intersect: closest hit of every ray in the current ray queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), rayOrigin, rayDirection, BVH.
// Out: hits[path] = (t, b1, b2, triangle), (t, -, -, WF_SPHERE_HIT | light) or WF_MISS.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"

#define WF_BVH_NODE(i) bvhNodes[i]
#define WF_BVH_TRIANGLE(i) triangles[i]
#include "bvh_traverse.h"
#include "light_sampling.h"

layout(push_constant) uniform Push { PassConstants pass; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.rayArgs.count)
        return;
    uint path = rayQueues[(pass.depth & 1u) * params.pathCapacity + index];
    vec3 origin = rayOrigin[path].xyz;
    vec3 direction = rayDirection[path].xyz;
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
        float t = raySphereNear(origin, direction, lights[i].position, lights[i].radius, false);
        if (t > 0.0 && t < closest) {
            closest = t;
            result = uvec4(floatBitsToUint(t), 0u, 0u, WF_SPHERE_HIT | i);
        }
    }
#endif
    hits[path] = result;
}
