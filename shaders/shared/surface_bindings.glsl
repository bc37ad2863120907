// Buffers of per-triangle vertex attributes and textures (bindings 20-31, texture_types.h).
// Each is declared only in the variants that read it, so a scene without textures binds no
// texel, texture-reference or UV buffer. Include after bindings.glsl.
#ifndef WF_SURFACE_BINDINGS_GLSL
#define WF_SURFACE_BINDINGS_GLSL
#include "texture_types.h"

#if WF_HAS_NORMALS
layout(std430, binding = WF_BINDING_NORMALS) readonly buffer NormalBuffer {
    TriangleNormals vertexNormals[];
};
#endif
#if WF_HAS_NORMAL_MAPS
layout(std430, binding = WF_BINDING_TANGENTS) readonly buffer TangentBuffer {
    TriangleTangents vertexTangents[];
};
#endif
#if WF_HAS_TEXTURES
layout(std430, binding = WF_BINDING_TEXTURE_REFS) readonly buffer TextureRefBuffer {
    TextureRef textureRefs[];
};
layout(std430, binding = WF_BINDING_TEXCOORDS0) readonly buffer Texcoord0Buffer {
    TriangleUvs texcoords0[];
};
#if WF_HAS_TEXCOORD1
layout(std430, binding = WF_BINDING_TEXCOORDS1) readonly buffer Texcoord1Buffer {
    TriangleUvs texcoords1[];
};
#endif
layout(std430, binding = WF_BINDING_TEXELS0) readonly buffer TexelPage0 { uint texels0[]; };
#if WF_TEXEL_PAGES > 1
layout(std430, binding = WF_BINDING_TEXELS0 + 1) readonly buffer TexelPage1 { uint texels1[]; };
#endif
#if WF_TEXEL_PAGES > 2
layout(std430, binding = WF_BINDING_TEXELS0 + 2) readonly buffer TexelPage2 { uint texels2[]; };
#endif
#if WF_TEXEL_PAGES > 3
layout(std430, binding = WF_BINDING_TEXELS0 + 3) readonly buffer TexelPage3 { uint texels3[]; };
#endif
#endif

#endif
