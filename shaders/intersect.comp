#version 460
// intersect: closest hit of every ray in the current ray queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), rayOrigin, rayDirection, BVH.
// Out: hits[path] = (t, b1, b2, triangle) or triangle = WF_MISS.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"

#define WF_BVH_NODE(i) bvhNodes[i]
#define WF_BVH_TRIANGLE(i) triangles[i]
#include "bvh_traverse.h"

layout(push_constant) uniform Push { PassConstants pass; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.rayArgs.count)
        return;
    uint path = rayQueues[(pass.depth & 1u) * params.pathCapacity + index];
    HitRecord hit;
    uvec4 result = uvec4(0u, 0u, 0u, WF_MISS);
    if (traceClosest(rayOrigin[path].xyz, rayDirection[path].xyz, 3.0e38, hit))
        result = uvec4(floatBitsToUint(hit.t), floatBitsToUint(hit.b1), floatBitsToUint(hit.b2),
                       hit.triangle);
    hits[path] = result;
}
