#version 460
// intersect: closest hit of every ray in the current ray queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), rayOrigin, rayDirection, BVH.
// Out: hits[index] (by queue slot: shade reads the same queue) = (t, b1, b2, triangle),
// (t, -, -, WF_SPHERE_HIT | light) or WF_MISS. With WF_SHADE_BINS > 1 it also appends the
// slot to kindQueues of the hit material's shade bin (counters.kindCount), and keeps each
// bin's group count in counters.kindArgs, which the bin's shade pass dispatches by.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#include "traversal/scene_intersect.glsl"
#if WF_SHADE_BINS > 1
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_ballot : require
#endif

layout(push_constant) uniform Push { PassConstants pass; };

#if WF_SHADE_BINS > 1
#include "wave/shade_bin.glsl"

// A ballot append (queue_append.glsl) that also raises the bin's group count to cover the
// slots taken: the shade pass's indirect arguments without a pass of their own (one such
// pass, a single invocation, cost 1-3 ms a frame with lavapipe's four threads). The queue
// pass zeroes both for the next bounce.
uint appendToBin(uint bin, bool wants) {
    uvec4 ballot = subgroupBallot(wants);
    uint total = subgroupBallotBitCount(ballot);
    uint base = 0u;
    if (total > 0u) {
        if (subgroupElect()) {
            base = atomicAdd(counters.kindCount[bin], total);
            atomicMax(counters.kindArgs[bin].groupsX,
                      (base + total + WF_WORKGROUP_SIZE - 1u) / WF_WORKGROUP_SIZE);
        }
        base = subgroupBroadcastFirst(base);
    }
    return base + subgroupBallotExclusiveBitCount(ballot);
}
#endif

void main() {
    uint index = gl_GlobalInvocationID.x;
#if WF_SHADE_BINS > 1
    bool inQueue = index < counters.rayArgs.count;
    uint bin = WF_SHADE_BINS;
    if (inQueue) {
        uint path = rayQueueAt(pass.depth, index);
#if WF_MOTION
        wfRayTime = rayTime[path];
#endif
        uvec4 hit = intersectClosest(rayOriginAt(path).xyz, rayDirectionAt(path).xyz);
        hits[index] = wfPack(hit);
        bin = shadeBinOf(hit);
    }
    // Appends in uniform control flow: every lane of the subgroup takes part in each. Binned
    // by lane, not by subgroup: whole subgroups to one bin (the general one where their kinds
    // differ) sent half the rays of the mirror and glass scene to the general pass.
    uint slot = 0u;
    for (uint b = 0u; b < WF_SHADE_BINS; ++b) {
        uint s = appendToBin(b, bin == b);
        slot = bin == b ? s : slot;
    }
    if (inQueue)
        kindQueues[bin * params.pathCapacity + slot] = index;
#else
    if (index >= counters.rayArgs.count)
        return;
    uint path = rayQueueAt(pass.depth, index);
#if WF_MOTION
    wfRayTime = rayTime[path];
#endif
    hits[index] = wfPack(intersectClosest(rayOriginAt(path).xyz, rayDirectionAt(path).xyz));
#endif
}
