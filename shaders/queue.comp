#version 460
// queue: turns the append counters into indirect-dispatch arguments for the next passes, then
// zeroes the counters for the next bounce, so the host never reads a count inside a wave.
// In/out: counters (with WF_SHADE_BINS, the shade bins' counts and group counts are zeroed
// too). One invocation; push constant depth: the bounce the shade pass just did.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 1) in;
#include "wave/bindings.glsl"

DispatchArgs argsFor(uint count) {
    return DispatchArgs((count + WF_WORKGROUP_SIZE - 1u) / WF_WORKGROUP_SIZE, 1u, 1u, count);
}

layout(push_constant) uniform Push { PassConstants pass; };

void main() {
    uint rays = counters.rayCount;
    uint shadows = counters.shadowCount;
    counters.rayArgs = argsFor(rays);
    counters.shadowArgs = argsFor(shadows);
#ifdef WF_RAY_TRACING // the ray-traced passes' arguments
    counters.rayTrace = TraceArgs(rays, 1u, 1u, 0u);
    counters.shadowTrace = TraceArgs(shadows, 1u, 1u, 0u);
#endif
    counters.extensionRays += rays;
    counters.shadowRays += shadows;
    // Occupancy per bounce: the rays just queued are traced at depth + 1.
    counters.depthRays[min(pass.depth + 1u, WF_TRACKED_DEPTHS - 1u)] += rays;
    counters.depthShadowRays[min(pass.depth, WF_TRACKED_DEPTHS - 1u)] += shadows;
    counters.rayCount = 0u;
    counters.shadowCount = 0u;
#if WF_SHADE_BINS > 1
    // The next bounce's intersect fills the shade bins afresh (their groupsY, groupsZ stay 1).
    for (uint b = 0u; b < WF_SHADE_BINS; ++b) {
        counters.kindCount[b] = 0u;
        counters.kindArgs[b].groupsX = 0u;
    }
#endif
}
