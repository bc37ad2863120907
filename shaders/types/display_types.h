// The viewer's display pass (shaders/display.comp): its push constants and the tone curves,
// shared with C++ so that tests/viewer/test_display_math.cpp checks on the CPU exactly what
// the GPU shows. Film and window may differ in size (the low-resolution preview while the
// camera moves); the pass samples the film nearest-neighbour.
#ifndef WF_DISPLAY_TYPES_H
#define WF_DISPLAY_TYPES_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_TONEMAP_LINEAR 0u
#define WF_TONEMAP_ACES 1u
#define WF_TONEMAP_NEUTRAL 2u

// Only 4-byte scalars, so std430 (push constants) and C++ agree member by member.
struct DisplayConstants {
    uint filmWidth;
    uint filmHeight;
    uint outWidth;
    uint outHeight;
    float exposureScale; // 2^EV, applied to the mean radiance before the tone curve
    uint tonemap;        // WF_TONEMAP_*
    uint pad0;
    uint pad1;
};

// Narkowicz 2015, "ACES Filmic Tone Mapping Curve": a rational fit of the ACES RRT + ODT
// luminance response, applied per channel. Maps 0 to 0, is monotonic, and reaches 1 only at
// about x = 16 (linear clips at 1), so highlights roll off instead of clipping.
WF_INLINE vec3 tonemapAces(vec3 x) {
    vec3 y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return clamp(y, vec3(0.0f), vec3(1.0f));
}

// Khronos PBR Neutral (the Khronos 3D Commerce group's tone mapper, 2024; what glTF viewers,
// Blender and three.js offer): base colours up to 0.8 come out as they went in (less a small
// offset that lifts near-black), brighter colours are compressed towards 1 along a curve that
// keeps their hue, and very bright ones desaturate towards white, so a material looks as its
// glTF file says it does.
WF_INLINE vec3 tonemapNeutral(vec3 color) {
    const float startCompression = 0.8f - 0.04f;
    const float desaturation = 0.15f;
    float lowest = min(color.x, min(color.y, color.z));
    float offset = lowest < 0.08f ? lowest - 6.25f * lowest * lowest : 0.04f;
    color -= vec3(offset);
    float peak = max(color.x, max(color.y, color.z));
    if (peak < startCompression)
        return clamp(color, vec3(0.0f), vec3(1.0f));
    const float d = 1.0f - startCompression;
    float newPeak = 1.0f - d * d / (peak + d - startCompression);
    color *= newPeak / peak;
    float g = 1.0f - 1.0f / (desaturation * (peak - newPeak) + 1.0f);
    return clamp(mix(color, vec3(newPeak), g), vec3(0.0f), vec3(1.0f));
}

// Non-negative radiance (exposure applied) to [0, 1] by the curve `tonemap` names.
WF_INLINE vec3 tonemapRadiance(vec3 radiance, uint tonemap) {
    if (tonemap == WF_TONEMAP_ACES)
        return tonemapAces(radiance);
    if (tonemap == WF_TONEMAP_NEUTRAL)
        return tonemapNeutral(radiance);
    return clamp(radiance, vec3(0.0f), vec3(1.0f));
}

// IEC 61966-2-1 encoding of one channel in [0, 1], as the PNG preview writes it.
WF_INLINE float srgbEncode(float v) {
    return v <= 0.0031308f ? 12.92f * v : 1.055f * pow(v, 1.0f / 2.4f) - 0.055f;
}

// On the bit pattern, as accumulate.comp does, so that no fast-math folding can drop it.
WF_INLINE bool isFiniteColor(vec3 v) {
    uvec3 exponent = floatBitsToUint(v) & uvec3(0x7f800000u);
    return all(notEqual(exponent, uvec3(0x7f800000u)));
}

// Mean radiance to display-ready sRGB in [0, 1]. Non-finite values (a film sum that
// overflowed) show black, as in the PNG preview; so does a pixel without samples yet.
WF_INLINE vec3 displayColor(vec4 filmTexel, float exposureScale, uint tonemap) {
    if (filmTexel.w <= 0.0f)
        return vec3(0.0f);
    vec3 radiance = exposureScale * vec3(filmTexel.x, filmTexel.y, filmTexel.z) / filmTexel.w;
    if (!isFiniteColor(radiance))
        return vec3(0.0f);
    radiance = max(radiance, vec3(0.0f));
    vec3 mapped = tonemapRadiance(radiance, tonemap);
    return vec3(srgbEncode(mapped.x), srgbEncode(mapped.y), srgbEncode(mapped.z));
}

#ifdef __cplusplus
static_assert(sizeof(DisplayConstants) == 32, "DisplayConstants must match display.comp");
} // namespace wf::gpu_types
#endif

#endif
