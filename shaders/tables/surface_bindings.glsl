// Per-triangle vertex attributes and textures (bindings 20-31, texture_types.h), bound as
// uint storage texel buffers like the scene tables (src/gpu/compute_program.h says why) and
// unpacked here into the structs of texture_types.h with the bits as stored: normals, tangents
// and texture references RGBA32UI, UVs RG32UI (a corner a texel), texel pages R32UI (an RGBA8
// texel a texel). Each is declared only in the variants that read it, so a scene without textures
// binds no texel, texture-reference or UV buffer. Include after bindings.glsl.
#ifndef WF_SURFACE_BINDINGS_GLSL
#define WF_SURFACE_BINDINGS_GLSL
#include "types/texture_types.h"

// The per-triangle arrays are paged where the triangles are (WF_TRIANGLE_PAGES), so that one
// page index serves them all.
#if WF_HAS_NORMALS
#define WF_PAGED_NAME normalTexel
#define WF_PAGED_FORMAT rgba32ui
#define WF_PAGED_BINDING WF_BINDING_NORMALS
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_NORMAL_PAGE1
#define WF_PAGED_PAGES WF_TRIANGLE_PAGES
#define WF_PAGED_SHIFT WF_TRIANGLE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_TRIANGLE_NORMALS_TEXELS
#include "tables/paged_table.glsl"

TriangleNormals triangleNormalsAt(uint triangle) {
    uvec4 t = normalTexel(triangle, 0u);
    return TriangleNormals(t.x, t.y, t.z, t.w);
}
#endif

#if WF_HAS_VERTEX_COLORS
#define WF_PAGED_NAME vertexColorTexel
#define WF_PAGED_FORMAT rgba32ui
#define WF_PAGED_BINDING WF_BINDING_VERTEX_COLORS
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_VERTEX_COLOR_PAGE1
#define WF_PAGED_PAGES WF_TRIANGLE_PAGES
#define WF_PAGED_SHIFT WF_TRIANGLE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_TRIANGLE_COLORS_TEXELS
#include "tables/paged_table.glsl"

// COLOR_0 at barycentrics (b1, b2) of a triangle, linear RGBA.
vec4 vertexColorAt(uint triangle, float b1, float b2) {
    uvec4 t = vertexColorTexel(triangle, 0u);
    return (1.0 - b1 - b2) * unpackUnorm4x8(t.x) + b1 * unpackUnorm4x8(t.y) +
           b2 * unpackUnorm4x8(t.z);
}
#endif

#if WF_HAS_NORMAL_MAPS || WF_HAS_TANGENTS
#define WF_PAGED_NAME tangentTexel
#define WF_PAGED_FORMAT rgba32ui
#define WF_PAGED_BINDING WF_BINDING_TANGENTS
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_TANGENT_PAGE1
#define WF_PAGED_PAGES WF_TRIANGLE_PAGES
#define WF_PAGED_SHIFT WF_TRIANGLE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_TRIANGLE_TANGENTS_TEXELS
#include "tables/paged_table.glsl"

TriangleTangents triangleTangentsAt(uint triangle) {
    uvec4 t = tangentTexel(triangle, 0u);
    return TriangleTangents(t.x, t.y, t.z, t.w);
}
#endif

#if WF_HAS_TEXTURES
layout(binding = WF_BINDING_TEXTURE_REFS, rgba32ui) uniform readonly restrict uimageBuffer
    textureRefTexels;
#define WF_PAGED_NAME texcoord0Texel
#define WF_PAGED_FORMAT rg32ui
#define WF_PAGED_BINDING WF_BINDING_TEXCOORDS0
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_TEXCOORD0_PAGE1
#define WF_PAGED_PAGES WF_TRIANGLE_PAGES
#define WF_PAGED_SHIFT WF_TRIANGLE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_TRIANGLE_UVS_TEXELS
#include "tables/paged_table.glsl"
#if WF_HAS_TEXCOORD1
#define WF_PAGED_NAME texcoord1Texel
#define WF_PAGED_FORMAT rg32ui
#define WF_PAGED_BINDING WF_BINDING_TEXCOORDS1
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_TEXCOORD1_PAGE1
#define WF_PAGED_PAGES WF_TRIANGLE_PAGES
#define WF_PAGED_SHIFT WF_TRIANGLE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_TRIANGLE_UVS_TEXELS
#include "tables/paged_table.glsl"
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
#if WF_HAS_TEXCOORD1
    if (layer == 1u)
        return TriangleUvs(uintBitsToFloat(texcoord1Texel(triangle, 0u).xy),
                           uintBitsToFloat(texcoord1Texel(triangle, 1u).xy),
                           uintBitsToFloat(texcoord1Texel(triangle, 2u).xy));
#endif
    return TriangleUvs(uintBitsToFloat(texcoord0Texel(triangle, 0u).xy),
                       uintBitsToFloat(texcoord0Texel(triangle, 1u).xy),
                       uintBitsToFloat(texcoord0Texel(triangle, 2u).xy));
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
