#version 460
// shadow: any-hit visibility of each NEE connection in the shadow queue.
// In: shadowQueue (count in counters.shadowArgs.count), shadowOrigin/Direction/Radiance.
// Out: radiance[path] += shadowRadiance[path] when the segment t in (0, 1) is unoccluded.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"
#if !WF_HAS_EMITTERS
#error "the shadow pass exists only for scenes with emitters"
#endif

#define WF_BVH_NODE(i) bvhNodes[i]
#define WF_BVH_TRIANGLE(i) triangles[i]
#include "bvh_traverse.h"
#include "light_sampling.h"

void main() {
    uint index = gl_GlobalInvocationID.x;
    if (index >= counters.shadowArgs.count)
        return;
    uint path = shadowQueue[index];
    // The direction spans the whole segment; both ends are offset off their surfaces, so the
    // light's own triangle lies beyond t = 1 and the shading triangle before t = 0.
    vec3 origin = shadowOrigin[path].xyz;
    vec3 segment = shadowDirection[path].xyz;
    bool occluded = traceAny(origin, segment, 1.0);
#if WF_HAS_SPHERE_LIGHTS
    float length_ = length(segment);
    for (uint i = 0u; i < params.sphereLightCount && !occluded; ++i) {
        float t = raySphereNear(origin, segment / length_, lights[i].position, lights[i].radius,
                                false);
        occluded = t > 0.0 && t < length_;
    }
#endif
    if (!occluded)
        radiance[path].rgb += shadowRadiance[path].rgb;
}
