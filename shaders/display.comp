#version 460
// display (viewer only): tone maps the film's mean radiance for the window. Not part of a
// wave: it runs once per shown frame, after the frame's samples, on its own two bindings.
// In: film (vec4 per pixel: radiance sum, sample count), push constants (sizes, exposure,
// tone curve). Out: one RGBA8 sRGB texel per window pixel, packed R in the low byte, which
// the host copies into the image the overlay draws on.
#extension GL_GOOGLE_include_directive : require
layout(local_size_x = 64) in;
#include "types/display_types.h"

layout(std430, binding = 0) readonly buffer FilmBuffer {
    vec4 film[];
};
layout(std430, binding = 1) writeonly buffer OutputBuffer {
    uint pixels[];
};
layout(push_constant) uniform Push { DisplayConstants display; };

void main() {
    // Grid-stride loop: a 4K window has more pixels than 65,535 groups of 64 cover.
    uint count = display.outWidth * display.outHeight;
    uint stride = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
    for (uint i = gl_GlobalInvocationID.x; i < count; i += stride) {
        uint x = i % display.outWidth;
        uint y = i / display.outWidth;
        // Nearest film texel: the preview film is about an integer fraction of the window.
        uint fx = min(x * display.filmWidth / display.outWidth, display.filmWidth - 1u);
        uint fy = min(y * display.filmHeight / display.outHeight, display.filmHeight - 1u);
        vec3 color = displayColor(film[fy * display.filmWidth + fx], display.exposureScale,
                                  display.tonemap);
        pixels[i] = packUnorm4x8(vec4(color, 1.0));
    }
}
