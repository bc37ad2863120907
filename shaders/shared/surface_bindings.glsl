// Per-triangle vertex attributes and textures (bindings 20-31, texture_types.h), bound as
// uint storage texel buffers like the scene tables (src/gpu/compute_program.h says why) and
// unpacked here into the structs of texture_types.h with the bits as stored: normals, tangents
// and texture references RGBA32UI, UVs RG32UI (a corner a texel), texel pages R32UI (an RGBA8
// texel a texel). Each is declared only in the variants that read it, so a scene without textures
// binds no texel, texture-reference or UV buffer. Include after bindings.glsl.
#ifndef WF_SURFACE_BINDINGS_GLSL
#define WF_SURFACE_BINDINGS_GLSL
#include "texture_types.h"

#if WF_HAS_NORMALS
layout(binding = WF_BINDING_NORMALS, rgba32ui) uniform readonly restrict uimageBuffer normalTexels;

TriangleNormals triangleNormalsAt(uint triangle) {
    uvec4 t = imageLoad(normalTexels, int(triangle * WF_TRIANGLE_NORMALS_TEXELS));
    return TriangleNormals(t.x, t.y, t.z, t.w);
}
#endif

#if WF_HAS_NORMAL_MAPS
layout(binding = WF_BINDING_TANGENTS, rgba32ui) uniform readonly restrict uimageBuffer
    tangentTexels;

TriangleTangents triangleTangentsAt(uint triangle) {
    uvec4 t = imageLoad(tangentTexels, int(triangle * WF_TRIANGLE_TANGENTS_TEXELS));
    return TriangleTangents(t.x, t.y, t.z, t.w);
}
#endif

#if WF_HAS_TEXTURES
layout(binding = WF_BINDING_TEXTURE_REFS, rgba32ui) uniform readonly restrict uimageBuffer
    textureRefTexels;
layout(binding = WF_BINDING_TEXCOORDS0, rg32ui) uniform readonly restrict uimageBuffer
    texcoord0Texels;
#if WF_HAS_TEXCOORD1
layout(binding = WF_BINDING_TEXCOORDS1, rg32ui) uniform readonly restrict uimageBuffer
    texcoord1Texels;
#endif
layout(binding = WF_BINDING_TEXELS0, r32ui) uniform readonly restrict uimageBuffer texelPage0;
#if WF_TEXEL_PAGES > 1
layout(binding = WF_BINDING_TEXELS0 + 1, r32ui) uniform readonly restrict uimageBuffer texelPage1;
#endif
#if WF_TEXEL_PAGES > 2
layout(binding = WF_BINDING_TEXELS0 + 2, r32ui) uniform readonly restrict uimageBuffer texelPage2;
#endif
#if WF_TEXEL_PAGES > 3
layout(binding = WF_BINDING_TEXELS0 + 3, r32ui) uniform readonly restrict uimageBuffer texelPage3;
#endif

TextureRef textureRefAt(uint index) {
    int base = int(index * WF_TEXTURE_REF_TEXELS);
    uvec4 a = imageLoad(textureRefTexels, base);
    uvec4 b = imageLoad(textureRefTexels, base + 1);
    uvec4 c = imageLoad(textureRefTexels, base + 2);
    return TextureRef(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w, c.x, c.y, c.z,
                      c.w);
}

// UV set `layer` (0: TEXCOORD_0, 1: TEXCOORD_1) at a triangle's corners.
TriangleUvs triangleUvsAt(uint layer, uint triangle) {
    int base = int(triangle * WF_TRIANGLE_UVS_TEXELS);
#if WF_HAS_TEXCOORD1
    if (layer == 1u)
        return TriangleUvs(uintBitsToFloat(imageLoad(texcoord1Texels, base).xy),
                           uintBitsToFloat(imageLoad(texcoord1Texels, base + 1).xy),
                           uintBitsToFloat(imageLoad(texcoord1Texels, base + 2).xy));
#endif
    return TriangleUvs(uintBitsToFloat(imageLoad(texcoord0Texels, base).xy),
                       uintBitsToFloat(imageLoad(texcoord0Texels, base + 1).xy),
                       uintBitsToFloat(imageLoad(texcoord0Texels, base + 2).xy));
}

// One RGBA8 texel (packed as unpackUnorm4x8 reads it) of a texel page.
uint texelAt(uint page, uint index) {
#if WF_TEXEL_PAGES > 1
    if (page == 1u)
        return imageLoad(texelPage1, int(index)).x;
#endif
#if WF_TEXEL_PAGES > 2
    if (page == 2u)
        return imageLoad(texelPage2, int(index)).x;
#endif
#if WF_TEXEL_PAGES > 3
    if (page == 3u)
        return imageLoad(texelPage3, int(index)).x;
#endif
    return imageLoad(texelPage0, int(index)).x;
}
#endif

#endif
