// Texture sampling for the shading and alpha-test code: UVs interpolated from the per-triangle
// UV buffers, KHR_texture_transform, the sampler's wrap modes, bilinear (or nearest) filtering
// of RGBA8 texels, and sRGB decoding of colour textures per texel, before filtering, as
// hardware samplers do. With WF_RAY_CONES, shading lookups read the image's mip chain at the
// level the ray cone's footprint asks for (ray_cones.h), stochastic trilinear; alpha tests and
// light sampling read level 0. Compiled only in variants with WF_HAS_TEXTURES.
#ifndef WF_TEXTURES_GLSL
#define WF_TEXTURES_GLSL
#include "tables/surface_bindings.glsl"

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

// One level of a reference's image: where it starts in the page and its size.
struct MipLevel {
    uint offset;
    int width;
    int height;
};

MipLevel baseLevel(TextureRef ref) { return MipLevel(ref.offset, int(ref.width), int(ref.height)); }

vec4 loadTexel(TextureRef ref, MipLevel level, int x, int y) {
    uint wrapS = ref.flags & 3u;
    uint wrapT = (ref.flags >> 2) & 3u;
    uint index = uint(wrapTexel(y, level.height, wrapT)) * uint(level.width) +
                 uint(wrapTexel(x, level.width, wrapS));
    vec4 texel = unpackUnorm4x8(texelAt(ref.page, level.offset + index));
    if ((ref.flags & WF_TEXTURE_SRGB) != 0u)
        texel.rgb = srgbToLinear(texel.rgb);
    return texel;
}

// Texture-space uv (transformed and reduced by the wrap modes) of the file's uv.
vec2 textureSpaceUv(TextureRef ref, vec2 uvFile) {
    vec3 h = vec3(uvFile, 1.0);
    vec2 uv = vec2(dot(ref.uRow, h), dot(ref.vRow, h));
    uv.x = reduceCoordinate(uv.x, ref.flags & 3u);
    uv.y = reduceCoordinate(uv.y, (ref.flags >> 2) & 3u);
    return uv;
}

vec4 sampleLevel(TextureRef ref, MipLevel level, vec2 uv) {
    vec2 size = vec2(float(level.width), float(level.height));
    if ((ref.flags & WF_TEXTURE_NEAREST) != 0u) {
        ivec2 texel = ivec2(floor(uv * size));
        return loadTexel(ref, level, texel.x, texel.y);
    }
    vec2 st = uv * size - 0.5; // texel centres sit at half-integers
    vec2 base = floor(st);
    vec2 f = st - base;
    int x = int(base.x);
    int y = int(base.y);
    vec4 top = mix(loadTexel(ref, level, x, y), loadTexel(ref, level, x + 1, y), f.x);
    vec4 bottom = mix(loadTexel(ref, level, x, y + 1), loadTexel(ref, level, x + 1, y + 1), f.x);
    return mix(top, bottom, f.y);
}

// RGBA (linear; alpha as stored) of texture reference `ref` at the file's uv, from level 0.
vec4 sampleTexture(TextureRef ref, vec2 uvFile) {
    return sampleLevel(ref, baseLevel(ref), textureSpaceUv(ref, uvFile));
}

// Samples reference `refIndex` on triangle `triangle` at barycentrics (b1, b2).
vec4 sampleTriangleTexture(uint refIndex, uint triangle, float b1, float b2) {
    TextureRef ref = textureRefAt(refIndex);
    return sampleTexture(ref, textureUv(triangle, ref.flags, b1, b2));
}

#if WF_RAY_CONES
#include "surface/ray_cones.h"

// The level below `level`: max(1, width >> 1) x max(1, height >> 1), right after it.
MipLevel nextLevel(MipLevel level) {
    return MipLevel(level.offset + uint(level.width * level.height), max(1, level.width >> 1),
                    max(1, level.height >> 1));
}

// Level k of the chain: max(1, width >> k) x max(1, height >> k), after the levels above it.
MipLevel mipLevel(TextureRef ref, uint k) {
    MipLevel level = baseLevel(ref);
    for (uint i = 0u; i < k; ++i)
        level = nextLevel(level);
    return level;
}

// The level a hit asks for (ray_cones.h): `footprint` is the cone's part (loadSurface); the
// texel area is twice the UV triangle's, through the texture transform, times the image's
// texels.
float textureLod(TextureRef ref, TriangleUvs uvs, float footprint) {
    vec2 e1 = uvs.uv1 - uvs.uv0;
    vec2 e2 = uvs.uv2 - uvs.uv0;
    float uvArea2 = abs(e1.x * e2.y - e1.y * e2.x) *
                    abs(ref.uRow.x * ref.vRow.y - ref.uRow.y * ref.vRow.x);
    return coneTextureLod(footprint, uvArea2 * float(ref.width) * float(ref.height), ref.levels);
}

// Which of the two levels around the footprint's a lookup reads: a hash of the hit, uniform in
// [0, 1), against the fraction. Inputs differ per sample (the barycentrics) and per texture.
float levelChoice(uint refIndex, uint triangle, float b1, float b2) {
    uint h = (floatBitsToUint(b1) * 0x9e3779b9u) ^ floatBitsToUint(b2);
    h ^= triangle * 0x85ebca6bu + refIndex * 0xc2b2ae35u;
    h ^= h >> 16; // lowbias32 (Wellons)
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return float(h >> 8) * (1.0 / 16777216.0);
}

// Stochastic trilinear filtering (Pharr et al., "Filtering After Shading With Stochastic
// Texture Filtering", 2024): one bilinear lookup of level k or k + 1, the coarser with
// probability lod - k. Its expected value is the trilinear blend, at half the texel fetches
// and sRGB decodes (on lavapipe, which runs both sides of every branch, the blend of two
// lookups cost the shade pass 1.5-2x on a textured floor); the pixel's samples average the
// choice away like any other.
vec4 sampleTriangleTextureCone(uint refIndex, uint triangle, float b1, float b2,
                               float footprint) {
    TextureRef ref = textureRefAt(refIndex);
    TriangleUvs uvs = triangleUvsAt((ref.flags & WF_TEXTURE_TEXCOORD1) != 0u ? 1u : 0u, triangle);
    vec2 uv = textureSpaceUv(ref, interpolateUv(uvs, b1, b2));
    float lod = textureLod(ref, uvs, footprint);
    uint k = uint(lod);
    bool coarser = levelChoice(refIndex, triangle, b1, b2) < lod - float(k);
    // At the last level lod - k is 0 (the clamp), so the choice never steps past the chain.
    return sampleLevel(ref, mipLevel(ref, coarser ? k + 1u : k), uv);
}
#endif
#endif
#endif
