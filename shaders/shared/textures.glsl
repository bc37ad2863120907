// Texture sampling for the shading and alpha-test code: UVs interpolated from the per-triangle
// UV buffers, KHR_texture_transform, the sampler's wrap modes, bilinear (or nearest) filtering
// of RGBA8 texels, and sRGB decoding of colour textures per texel, before filtering, as
// hardware samplers do. No mipmaps: the path tracer's pixel jitter averages what a mipmap
// would. Compiled only in variants with WF_HAS_TEXTURES.
#ifndef WF_TEXTURES_GLSL
#define WF_TEXTURES_GLSL
#include "surface_bindings.glsl"

#if WF_HAS_TEXTURES

vec2 interpolateUv(TriangleUvs uvs, float b1, float b2) {
    return (1.0 - b1 - b2) * uvs.uv0 + b1 * uvs.uv1 + b2 * uvs.uv2;
}

// The UV set a texture reference reads, at barycentrics (b1, b2) of a triangle.
vec2 textureUv(uint triangle, uint flags, float b1, float b2) {
    uint layer = (flags & WF_TEXTURE_TEXCOORD1) != 0u ? 1u : 0u;
    return interpolateUv(triangleUvsAt(layer, triangle), b1, b2);
}

// Folds a texel coordinate into [0, n) by the wrap mode. uv was already reduced to a small
// range, so i is within a few periods; the final clamp keeps even NaN-born values in bounds.
int wrapTexel(int i, int n, uint mode) {
    if (mode == WF_WRAP_CLAMP)
        return clamp(i, 0, n - 1);
    if (mode == WF_WRAP_MIRROR) {
        int m = ((i % (2 * n)) + 2 * n) % (2 * n);
        return clamp(m < n ? m : 2 * n - 1 - m, 0, n - 1);
    }
    return clamp(((i % n) + n) % n, 0, n - 1);
}

// Keeps float-to-int conversions small: repeat modes only need uv modulo their period.
float reduceCoordinate(float u, uint mode) {
    if (mode == WF_WRAP_CLAMP)
        return clamp(u, -1.0, 2.0);
    float period = mode == WF_WRAP_MIRROR ? 2.0 : 1.0;
    return u - period * floor(u / period);
}

vec3 srgbToLinear(vec3 c) {
    vec3 low = c / 12.92;
    vec3 high = pow((c + 0.055) / 1.055, vec3(2.4));
    return mix(high, low, lessThanEqual(c, vec3(0.04045)));
}

vec4 loadTexel(TextureRef ref, int x, int y) {
    int w = int(ref.width);
    int h = int(ref.height);
    uint wrapS = ref.flags & 3u;
    uint wrapT = (ref.flags >> 2) & 3u;
    uint index = uint(wrapTexel(y, h, wrapT)) * ref.width + uint(wrapTexel(x, w, wrapS));
    vec4 texel = unpackUnorm4x8(texelAt(ref.page, ref.offset + index));
    if ((ref.flags & WF_TEXTURE_SRGB) != 0u)
        texel.rgb = srgbToLinear(texel.rgb);
    return texel;
}

// RGBA (linear; alpha as stored) of texture reference `ref` at the file's uv.
vec4 sampleTexture(TextureRef ref, vec2 uvFile) {
    vec3 h = vec3(uvFile, 1.0);
    vec2 uv = vec2(dot(ref.uRow, h), dot(ref.vRow, h));
    uv.x = reduceCoordinate(uv.x, ref.flags & 3u);
    uv.y = reduceCoordinate(uv.y, (ref.flags >> 2) & 3u);
    vec2 size = vec2(float(ref.width), float(ref.height));
    if ((ref.flags & WF_TEXTURE_NEAREST) != 0u) {
        ivec2 texel = ivec2(floor(uv * size));
        return loadTexel(ref, texel.x, texel.y);
    }
    vec2 st = uv * size - 0.5; // texel centres sit at half-integers
    vec2 base = floor(st);
    vec2 f = st - base;
    int x = int(base.x);
    int y = int(base.y);
    vec4 top = mix(loadTexel(ref, x, y), loadTexel(ref, x + 1, y), f.x);
    vec4 bottom = mix(loadTexel(ref, x, y + 1), loadTexel(ref, x + 1, y + 1), f.x);
    return mix(top, bottom, f.y);
}

// Samples reference `refIndex` on triangle `triangle` at barycentrics (b1, b2).
vec4 sampleTriangleTexture(uint refIndex, uint triangle, float b1, float b2) {
    TextureRef ref = textureRefAt(refIndex);
    return sampleTexture(ref, textureUv(triangle, ref.flags, b1, b2));
}

#endif
#endif
