#version 460
// shadow: any-hit visibility of each NEE connection in the shadow queue.
// In: the shadow queue (count in counters.shadowArgs.count): shadowOrigin (with the path in
// w), shadowDirection (with the sphere light it ends on in w) and shadowRadiance at each
// queue slot.
// Out: radiance[path] += shadowRadiance[slot] when the segment t in (0, 1) is unoccluded.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "wave/bindings.glsl"
#if !WF_HAS_EMITTERS
#error "the shadow pass exists only for scenes with emitters"
#endif
#include "traversal/scene_intersect.glsl"

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.shadowArgs.count)
        return;
    uvec4 origin = shadowOriginAt(index);
    uint path = origin.w;
#if WF_MOTION
    wfRayTime = rayTime[path]; // the connection is made at the path's time
#endif
    // The segment spans the whole connection; both ends are offset off their surfaces, so the
    // shading triangle lies before t = 0, and the light it ends on is left out of the test.
    vec4 segment = shadowDirectionAt(index);
    if (!segmentOccluded(uintBitsToFloat(origin.xyz), segment.xyz, uint(segment.w) - 1u))
        radiance[path] = wfPack(vec4(radianceAt(path).rgb + shadowRadianceAt(index).rgb, 0.0));
}
