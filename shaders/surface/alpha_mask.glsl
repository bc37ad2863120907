// The alpha test bvh_traverse.h calls (WF_HAS_ALPHA_MASK variants) for every candidate hit, so
// cut-outs stop camera, continuation and shadow rays alike.
//   MASK:  the surface exists where alpha >= alphaCutoff (glTF).
//   BLEND: stochastic transparency: the ray stops with probability alpha, decided by a hash
//          of the ray and triangle. Unbiased for a path tracer (the expected transmittance is
//          1 - alpha), reproducible for a given seed, and order-independent, unlike blending.
// alpha = baseColorFactor.a x baseColorTexture.a x COLOR_0.a.
#ifndef WF_ALPHA_MASK_GLSL
#define WF_ALPHA_MASK_GLSL
#include "surface/textures.glsl"

uint alphaHash(uvec4 v) {
    // Two rounds of a 32-bit integer mix (Jarzynski and Olano's PCG-style hash, folded).
    uint h = v.x * 747796405u + 2891336453u;
    h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
    h ^= v.y + 0x9e3779b9u + (h << 6) + (h >> 2);
    h ^= v.z + 0x9e3779b9u + (h << 6) + (h >> 2);
    h ^= v.w + 0x9e3779b9u + (h << 6) + (h >> 2);
    h = h * 747796405u + 2891336453u;
    return ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
}

bool wfAlphaPasses(uint triangle, float b1, float b2, vec3 o, vec3 d) {
    uint material = triangleAt(triangle).material;
    uint flags = materialAt(material).flags;
    if ((flags & (WF_MATERIAL_ALPHA_MASK | WF_MATERIAL_ALPHA_BLEND)) == 0u)
        return true;
    float alpha = materialAt(material).baseColor.a;
#if WF_HAS_TEXTURES
    uint baseTexture = materialAt(material).baseColorTexture;
    if (baseTexture != WF_NO_TEXTURE)
        alpha *= sampleTriangleTexture(baseTexture, triangle, b1, b2).a;
#endif
#if WF_HAS_VERTEX_COLORS
    alpha *= vertexColorAt(triangle, b1, b2).a;
#endif
    if ((flags & WF_MATERIAL_ALPHA_MASK) != 0u)
        return alpha >= materialAt(material).alphaCutoff;
    uvec3 ob = floatBitsToUint(o) ^ (floatBitsToUint(d) * 0x9e3779b9u);
    uint h = alphaHash(uvec4(ob, triangle));
    return float(h >> 8) * (1.0 / 16777216.0) < alpha;
}

#endif
