// Per-triangle vertex attributes and textures as the GPU reads them: uint texel buffers that
// surface_bindings.glsl unpacks into these structs, so each struct is a whole number of texels
// (WF_*_TEXELS, asserted below). Every buffer here exists only for scenes that use it (see
// src/render/gpu_scene/surface_buffers.cpp): a scene without textures has no texel, texture-reference or
// UV buffer, one without smooth normals no normal buffer. Included by C++ and GLSL; the C++
// side asserts the layout.
#ifndef WF_TEXTURE_TYPES_H
#define WF_TEXTURE_TYPES_H

#include "types/glsl_cpp.h"

// Per-scene switches (src/render/shader_variant.cpp); off unless the host turns them on.
#ifndef WF_HAS_TEXTURES
#define WF_HAS_TEXTURES 0
#endif
#ifndef WF_TEXEL_PAGES
#define WF_TEXEL_PAGES 0
#endif
#ifndef WF_HAS_TEXCOORD1
#define WF_HAS_TEXCOORD1 0
#endif
#ifndef WF_HAS_NORMALS
#define WF_HAS_NORMALS 0
#endif
#ifndef WF_HAS_NORMAL_MAPS
#define WF_HAS_NORMAL_MAPS 0
#endif
#ifndef WF_HAS_TANGENTS // tangent frames for KHR_materials_anisotropy
#define WF_HAS_TANGENTS 0
#endif
#ifndef WF_HAS_ALPHA_MASK
#define WF_HAS_ALPHA_MASK 0
#endif
#ifndef WF_HAS_VERTEX_COLORS
#define WF_HAS_VERTEX_COLORS 0
#endif
// WF_RAY_CONES (render_types.h): textures filtered from their mip chains by ray cones.

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// Bindings 20-31 and 71-98 of the shared descriptor set (render_types.h keeps the others).
#define WF_BINDING_TEXTURE_REFS 20
#define WF_BINDING_NORMALS 21
#define WF_BINDING_TANGENTS 22
#define WF_BINDING_TEXCOORDS0 23
#define WF_BINDING_TEXCOORDS1 24
#define WF_BINDING_TEXELS0 25 // texel pages 0..3: images split across buffers so that none
#define WF_MAX_TEXEL_PAGES 4  // passes the device's per-buffer limit (lavapipe: 128 MiB)
// Pages 1-7 of the per-triangle attributes, cut where the triangles' pages are (71-98)
#define WF_BINDING_NORMAL_PAGE1 71    // 71 .. 77
#define WF_BINDING_TANGENT_PAGE1 78   // 78 .. 84
#define WF_BINDING_TEXCOORD0_PAGE1 85 // 85 .. 91
#define WF_BINDING_TEXCOORD1_PAGE1 92 // 92 .. 98
#define WF_BINDING_VERTEX_COLORS 110       // COLOR_0 (WF_HAS_VERTEX_COLORS)
#define WF_BINDING_VERTEX_COLOR_PAGE1 111  // 111 .. 117

// TextureRef.flags: bits 0-1 wrap S, bits 2-3 wrap T, then switches.
#define WF_WRAP_REPEAT 0u
#define WF_WRAP_CLAMP 1u
#define WF_WRAP_MIRROR 2u
#define WF_TEXTURE_SRGB 16u      // colour data: sRGB-decode each texel before filtering
#define WF_TEXTURE_NEAREST 32u   // magFilter NEAREST; otherwise bilinear
#define WF_TEXTURE_TEXCOORD1 64u // sample with TEXCOORD_1 instead of TEXCOORD_0

// One material's use of one image: which texel page and where in it, how to wrap and filter,
// and the KHR_texture_transform as a 2x3 matrix: uv' = (dot(uRow, (u, v, 1)),
// dot(vRow, (u, v, 1))). Texels are RGBA8, one uint (one R32UI texel) each, rows top first;
// the image's mip chain follows it in the same page (level k is max(1, width >> k) x max(1,
// height >> k), src/scene/mip_chain.h).
struct TextureRef {
    vec3 uRow;
    uint page;
    vec3 vRow;
    uint offset; // first texel in the page
    uint width;
    uint height;
    uint flags;  // WF_WRAP_* | WF_TEXTURE_*
    uint levels; // mip levels stored, level 0 included
};
#define WF_TEXTURE_REF_TEXELS 3u // RGBA32UI

// Shading normals at a triangle's three corners (world space), each octahedral-encoded in two
// 16-bit snorms (packSnorm2x16): 16 bytes per triangle instead of 48.
struct TriangleNormals {
    uint n0;
    uint n1;
    uint n2;
    uint pad;
};
#define WF_TRIANGLE_NORMALS_TEXELS 1u // RGBA32UI

// COLOR_0 at a triangle's corners: linear RGBA, each packed as four unorm8 (packUnorm4x8);
// glTF multiplies the base colour (and its alpha) by it. Triangles of primitives without
// COLOR_0 hold opaque white.
struct TriangleColors {
    uint c0;
    uint c1;
    uint c2;
    uint pad;
};
#define WF_TRIANGLE_COLORS_TEXELS 1u // RGBA32UI

// Tangents at the corners, octahedral like the normals; bit k of `signs` set means corner k's
// bitangent is -cross(normal, tangent) (glTF TANGENT.w = -1, mirrored UVs).
struct TriangleTangents {
    uint t0;
    uint t1;
    uint t2;
    uint signs;
};
#define WF_TRIANGLE_TANGENTS_TEXELS 1u // RGBA32UI

// One UV set at a triangle's corners (TEXCOORD_0 or TEXCOORD_1), as the file gives them.
struct TriangleUvs {
    vec2 uv0;
    vec2 uv1;
    vec2 uv2;
};
#define WF_TRIANGLE_UVS_TEXELS 3u // RG32UI, one corner each

// Octahedral mapping of unit vectors onto [-1, 1]^2 (Cigolle et al. 2014): decode half, shared
// so the CPU tests check it against the C++ encoder in the loader.
WF_INLINE vec3 octDecode(vec2 e) {
    vec3 v = vec3(e.x, e.y, 1.0f - abs(e.x) - abs(e.y));
    if (v.z < 0.0f) {
        float x = (1.0f - abs(v.y)) * (v.x >= 0.0f ? 1.0f : -1.0f);
        float y = (1.0f - abs(v.x)) * (v.y >= 0.0f ? 1.0f : -1.0f);
        v.x = x;
        v.y = y;
    }
    return normalize(v);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::TextureRef) == 16 * WF_TEXTURE_REF_TEXELS);
static_assert(offsetof(wf::gpu_types::TextureRef, page) == 12);
static_assert(offsetof(wf::gpu_types::TextureRef, vRow) == 16);
static_assert(offsetof(wf::gpu_types::TextureRef, offset) == 28);
static_assert(offsetof(wf::gpu_types::TextureRef, flags) == 40);
static_assert(offsetof(wf::gpu_types::TextureRef, levels) == 44);
static_assert(sizeof(wf::gpu_types::TriangleNormals) == 16 * WF_TRIANGLE_NORMALS_TEXELS);
static_assert(sizeof(wf::gpu_types::TriangleTangents) == 16 * WF_TRIANGLE_TANGENTS_TEXELS);
static_assert(sizeof(wf::gpu_types::TriangleColors) == 16 * WF_TRIANGLE_COLORS_TEXELS);
static_assert(sizeof(wf::gpu_types::TriangleUvs) == 8 * WF_TRIANGLE_UVS_TEXELS);
static_assert(offsetof(wf::gpu_types::TriangleUvs, uv1) == 8);
static_assert(offsetof(wf::gpu_types::TriangleUvs, uv2) == 16);
#endif

#endif
