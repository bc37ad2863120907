#version 460
// raygen: one camera path per (pixel, sample) of the wave.
// In: params (camera, image size), push constants (sampleBase, pathCount).
// Out: rayOrigin/rayDirection/throughput/radiance of every path; rayQueue[0] = path index.
// Path p is sample p / pixelCount of pixel p % pixelCount, so accumulate needs no lookup.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = WF_WORKGROUP_SIZE) in;
#include "bindings.glsl"
#include "rng.h"

layout(push_constant) uniform Push { PassConstants pass; };

void main() {
    uint path = gl_GlobalInvocationID.x;
    if (path >= pass.pathCount)
        return;
    uint pixel = path % params.pixelCount;
    uint sampleIndex = pass.sampleBase + path / params.pixelCount;
    uint x = pixel % params.width;
    uint y = pixel / params.width;

    // Box filter: a uniform point inside the pixel; row 0 is the top of the image.
    vec2 jitter = sample2D(pixel, sampleIndex, WF_DIM_PIXEL, params.seed);
    vec2 ndc = (vec2(x, y) + jitter) / vec2(params.width, params.height) * 2.0 - 1.0;
    vec3 direction = params.cameraForward +
                     params.cameraRight * (ndc.x * params.tanHalfFovY * params.aspect) -
                     params.cameraUp * (ndc.y * params.tanHalfFovY);

    rayOrigin[path] = vec4(params.cameraPosition, 0.0);
    rayDirection[path] = vec4(normalize(direction), 0.0);
    throughput[path] = vec4(1.0);
    radiance[path] = vec4(0.0);
    rayQueues[path] = path;
}
