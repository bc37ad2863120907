#version 460
// intersect: closest hit of every ray in the current ray queue.
// In: rayQueue[depth & 1] (count in counters.rayArgs.count), rayOrigin, rayDirection, BVH.
// Out: hits[index] (by queue slot: shade reads the same queue) = (t, b1, b2, triangle),
// (t, -, -, WF_SPHERE_HIT | light) or WF_MISS. With WF_SHADE_BINS > 1 it also appends each
// subgroup's slots to one shade bin's kindQueues (counters.kindCount): the bin of its
// materials' kind where they share one, else the last (general) bin.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"
#include "scene_intersect.glsl"
#if WF_SHADE_BINS > 1
#include "queue_append.glsl"
WF_DEFINE_INDEXED_QUEUE_APPEND(appendToBin, counters.kindCount)
#endif

layout(push_constant) uniform Push { PassConstants pass; };

#if WF_SHADE_BINS > 1
#extension GL_KHR_shader_subgroup_arithmetic : require
// The bin rides in the material's flags (WF_MATERIAL_SHADE_BIN_SHIFT), texel 1 of its entry;
// misses and sphere-light hits shade alike in every bin (WF_SHADE_BINS: any).
uint shadeBinOf(uvec4 hit) {
    if (hit.w == WF_MISS || (hit.w & WF_SPHERE_HIT) != 0u)
        return WF_SHADE_BINS;
    uint material = triangleTexel(hit.w, 0u).w;
    uint flags = wfTexel(materialTexels,
                         WF_MATERIAL_TABLE_START + material * WF_MATERIAL_TEXELS + 1u).w;
    return (flags >> WF_MATERIAL_SHADE_BIN_SHIFT) & WF_MATERIAL_SHADE_BIN_MASK;
}
#endif

void main() {
    uint index = gl_GlobalInvocationID.x;
#if WF_SHADE_BINS > 1
    bool inQueue = index < counters.rayArgs.count;
    uint bin = WF_SHADE_BINS;
    if (inQueue) {
        uint path = rayQueueAt(pass.depth, index);
        uvec4 hit = intersectClosest(rayOriginAt(path).xyz, rayDirectionAt(path).xyz);
        hits[index] = wfPack(hit);
        bin = shadeBinOf(hit);
    }
    // Whole subgroups go to one bin: a shade subgroup then reads the 8 consecutive slots one
    // intersect subgroup wrote, and each pass touches its own cache lines of the path state.
    // Binned by lane, every pass touched nearly every line and shading cost 35% more.
    uint lowest = subgroupMin(bin);
    uint highest = subgroupMax(bin == WF_SHADE_BINS ? 0u : bin);
    uint subgroupBin = lowest == WF_SHADE_BINS ? WF_LIGHT_HIT_BIN
                       : lowest == highest     ? lowest
                                               : WF_SHADE_BINS - 1u;
    // In uniform control flow: every lane of the subgroup takes part.
    uint slot = appendToBin(subgroupBin, inQueue);
    if (inQueue)
        kindQueues[subgroupBin * params.pathCapacity + slot] = index;
#else
    if (index >= counters.rayArgs.count)
        return;
    uint path = rayQueueAt(pass.depth, index);
    hits[index] = wfPack(intersectClosest(rayOriginAt(path).xyz, rayDirectionAt(path).xyz));
#endif
}
