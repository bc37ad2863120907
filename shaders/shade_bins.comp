#version 460
// shade bins: turns the shade bins' append counters (filled by intersect) into the indirect
// arguments of the per-bin shade passes and zeroes them for the next bounce.
// In/out: counters.kindCount, counters.kindArgs. One invocation; only with WF_SHADE_BINS > 1.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 1) in;
#include "bindings.glsl"

void main() {
    for (uint b = 0u; b < WF_SHADE_BINS; ++b) {
        uint count = counters.kindCount[b];
        counters.kindArgs[b] =
            DispatchArgs((count + WF_WORKGROUP_SIZE - 1u) / WF_WORKGROUP_SIZE, 1u, 1u, count);
        counters.kindCount[b] = 0u;
    }
}
