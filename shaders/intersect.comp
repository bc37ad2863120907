#version 460
// intersect: closest hit of every ray in the current ray queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), rayOrigin, rayDirection, BVH.
// Out: hits[index] (by queue slot: shade reads the same queue) = (t, b1, b2, triangle),
// (t, -, -, WF_SPHERE_HIT | light) or WF_MISS.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"
#include "scene_intersect.glsl"

layout(push_constant) uniform Push { PassConstants pass; };

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.rayArgs.count)
        return;
    uint path = rayQueueAt(pass.depth, index);
    hits[index] = wfPack(intersectClosest(rayOriginAt(path).xyz, rayDirectionAt(path).xyz));
}
