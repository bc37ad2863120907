// The scene tables every ray and shading point reads at scattered indices, bound as RGBA32UI
// storage texel buffers read with imageLoad (src/gpu/compute_program.h says why) and unpacked
// into the structs of scene_types.h. Unused fields cost nothing: the compiler drops loads whose
// texel is unread.
// Triangles, BVH entries and instances may span several buffers ("pages", WF_TRIANGLE_PAGES,
// WF_BVH_PAGES and WF_INSTANCE_PAGES of 2^shift entries each) where one buffer would pass the
// device's limit (paged_table.glsl declares them and their readers: triangleTexel, bvhTexel,
// instanceTexel).
#define WF_PAGED_NAME triangleTexel
#define WF_PAGED_FORMAT rgba32ui
#define WF_PAGED_BINDING WF_BINDING_TRIANGLES
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_TRIANGLE_PAGE1
#define WF_PAGED_PAGES WF_TRIANGLE_PAGES
#define WF_PAGED_SHIFT WF_TRIANGLE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_TRIANGLE_TEXELS
#include "tables/paged_table.glsl"

#define WF_PAGED_NAME bvhTexel
#define WF_PAGED_FORMAT rgba32ui
#define WF_PAGED_BINDING WF_BINDING_BVH_NODES
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_BVH_PAGE1
#define WF_PAGED_PAGES WF_BVH_PAGES
#define WF_PAGED_SHIFT WF_BVH_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_BVH_PAIR_TEXELS
#include "tables/paged_table.glsl"

layout(binding = WF_BINDING_MATERIALS, rgba32ui) uniform readonly restrict uimageBuffer
    materialTexels;
#if WF_HAS_INSTANCES
#define WF_PAGED_NAME instanceTexel
#define WF_PAGED_FORMAT rgba32ui
#define WF_PAGED_BINDING WF_BINDING_INSTANCES
#define WF_PAGED_BINDING_PAGE1 WF_BINDING_INSTANCE_PAGE1
#define WF_PAGED_PAGES WF_INSTANCE_PAGES
#define WF_PAGED_SHIFT WF_INSTANCE_PAGE_SHIFT
#define WF_PAGED_TEXELS WF_INSTANCE_TEXELS
#include "tables/paged_table.glsl"
#endif
#if WF_HAS_EMITTERS
layout(binding = WF_BINDING_EMITTERS, rgba32ui) uniform readonly restrict uimageBuffer
    emitterTexels;
#endif
#if WF_HAS_EMITTERS && WF_LIGHT_TREE
layout(binding = WF_BINDING_LIGHT_TREE, rgba32ui) uniform readonly restrict uimageBuffer
    lightTreeTexels;
layout(binding = WF_BINDING_LIGHT_TREE_TRAILS, rgba32ui) uniform readonly restrict uimageBuffer
    lightTreeTrailTexels;
#endif
#if WF_HAS_LIGHTS
// Sphere lights first.
layout(binding = WF_BINDING_LIGHTS, rgba32ui) uniform readonly restrict uimageBuffer lightTexels;
#endif
#if WF_HAS_ENVIRONMENT
// RGB radiance per texel (alpha unused), equirectangular, top row first.
layout(binding = WF_BINDING_ENVIRONMENT, rgba32ui) uniform readonly restrict uimageBuffer
    environmentTexels;
#if WF_HAS_EMITTERS
// Emitter-shaped alias table over the environment's texels.
layout(binding = WF_BINDING_ENVIRONMENT_ALIAS, rgba32ui) uniform readonly restrict uimageBuffer
    environmentAliasTexels;
#endif
#endif

// A macro, as GLSL functions cannot take the images themselves.
#define wfTexel(table, index) imageLoad(table, int(index))


Triangle triangleAt(uint index) {
    uvec4 a = triangleTexel(index, 0u);
    uvec4 b = triangleTexel(index, 1u);
    uvec4 c = triangleTexel(index, 2u);
    return Triangle(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w,
                    uintBitsToFloat(c.xyz), c.w);
}

BvhPair bvhPairAt(uint index) {
    uvec4 a = bvhTexel(index, 0u);
    uvec4 b = bvhTexel(index, 1u);
    uvec4 c = bvhTexel(index, 2u);
    uvec4 d = bvhTexel(index, 3u);
    return BvhPair(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w,
                   uintBitsToFloat(c.xyz), c.w, uintBitsToFloat(d.xyz), d.w);
}

#if WF_HAS_SHEEN
#include "bsdf/sheen_albedo_table.h"
// The sheen albedo table (sheen.h) rides at the front of the material table, four nodes a texel.
#define WF_MATERIAL_TABLE_START WF_SHEEN_TABLE_TEXELS
float sheenAlbedoNode(int k) {
    return uintBitsToFloat(wfTexel(materialTexels, uint(k) >> 2)[k & 3]);
}
#else
#define WF_MATERIAL_TABLE_START 0u
#endif

Material materialAt(uint index) {
    uint base = WF_MATERIAL_TABLE_START + index * WF_MATERIAL_TEXELS;
    uvec4 t0 = wfTexel(materialTexels, base);
    uvec4 t1 = wfTexel(materialTexels, base + 1u);
    uvec4 t2 = wfTexel(materialTexels, base + 2u);
    uvec4 t3 = wfTexel(materialTexels, base + 3u);
    uvec4 t4 = wfTexel(materialTexels, base + 4u);
    uvec4 t5 = wfTexel(materialTexels, base + 5u);
    // The extensions' texels only where the scene uses them.
    uvec4 t6 = uvec4(WF_NO_TEXTURE, 0u, 0u, 0u);
    uvec4 t7 = uvec4(0u);
    uvec4 t8 = uvec4(0u);
#if WF_HAS_SPECULAR_TEXTURES || WF_HAS_CLEARCOAT
    t6 = wfTexel(materialTexels, base + 6u);
#endif
#if WF_HAS_SHEEN
    t7 = wfTexel(materialTexels, base + 7u);
#endif
#if WF_HAS_VOLUME
    t8 = wfTexel(materialTexels, base + 8u);
#endif
    uvec4 t9 = uvec4(0u);
    uvec4 t10 = uvec4(WF_NO_TEXTURE, WF_NO_TEXTURE, 0u, 0u);
#if WF_HAS_IRIDESCENCE
    t9 = wfTexel(materialTexels, base + 9u);
    t10 = wfTexel(materialTexels, base + 10u);
#endif
    // The layers' and volume's textures (texels 11-12), and the coat normal map's scale.
    uvec4 t11 = uvec4(WF_NO_TEXTURE, WF_NO_TEXTURE, WF_NO_TEXTURE, floatBitsToUint(1.0));
    uvec4 t12 = uvec4(WF_NO_TEXTURE, WF_NO_TEXTURE, WF_NO_TEXTURE, 0u);
#if WF_HAS_CLEARCOAT_TEXTURES || WF_HAS_CLEARCOAT_NORMAL_MAPS
    t11 = wfTexel(materialTexels, base + 11u);
#endif
#if WF_HAS_SHEEN_TEXTURES || WF_HAS_THICKNESS_TEXTURES
    t12 = wfTexel(materialTexels, base + 12u);
#endif
    // Anisotropy (texel 13): strength, texture, rotation (cos, sin).
    uvec4 t13 = uvec4(0u, WF_NO_TEXTURE, floatBitsToUint(1.0), 0u);
#if WF_HAS_ANISOTROPY
    t13 = wfTexel(materialTexels, base + 13u);
#endif
    // Diffuse transmission (texels 14-15): colour and factor, then the two textures; then
    // dispersion (texel 15's z).
    uvec4 t14 = uvec4(floatBitsToUint(1.0), floatBitsToUint(1.0), floatBitsToUint(1.0), 0u);
    uvec4 t15 = uvec4(WF_NO_TEXTURE, WF_NO_TEXTURE, 0u, 0u);
#if WF_HAS_DIFFUSE_TRANSMISSION
    t14 = wfTexel(materialTexels, base + 14u);
#endif
#if WF_HAS_DIFFUSE_TRANSMISSION || WF_HAS_DISPERSION
    t15 = wfTexel(materialTexels, base + 15u);
#endif
    return Material(uintBitsToFloat(t0), uintBitsToFloat(t1.xyz), t1.w, uintBitsToFloat(t2.x),
                    uintBitsToFloat(t2.y), uintBitsToFloat(t2.z), uintBitsToFloat(t2.w),
                    uintBitsToFloat(t3.xyz), uintBitsToFloat(t3.w), uintBitsToFloat(t4.x),
                    uintBitsToFloat(t4.y), t4.z, t4.w, t5.x, t5.y, t5.z, t5.w, t6.x,
                    uintBitsToFloat(t6.y), uintBitsToFloat(t6.z), t6.w, uintBitsToFloat(t7.xyz),
                    uintBitsToFloat(t7.w), uintBitsToFloat(t8.xyz), uintBitsToFloat(t8.w),
                    uintBitsToFloat(t9.x), uintBitsToFloat(t9.y), uintBitsToFloat(t9.z),
                    uintBitsToFloat(t9.w), t10.x, t10.y, t10.z, t10.w,
                    t11.x, t11.y, t11.z, uintBitsToFloat(t11.w), t12.x, t12.y, t12.z, t12.w,
                    uintBitsToFloat(t13.x), t13.y, uintBitsToFloat(t13.zw),
                    uintBitsToFloat(t14.xyz), uintBitsToFloat(t14.w), t15.x, t15.y, uintBitsToFloat(t15.z), t15.w);
}

#if WF_HAS_INSTANCES

// As stored; instanceAt (motion.glsl) places a moving one at the ray's time.
Instance instanceRecordAt(uint index) {
    uvec4 t6 = instanceTexel(index, 6u);
    return Instance(uintBitsToFloat(instanceTexel(index, 0u)),
                    uintBitsToFloat(instanceTexel(index, 1u)),
                    uintBitsToFloat(instanceTexel(index, 2u)),
                    uintBitsToFloat(instanceTexel(index, 3u)),
                    uintBitsToFloat(instanceTexel(index, 4u)),
                    uintBitsToFloat(instanceTexel(index, 5u)), t6.x, t6.y, t6.z, t6.w);
}
#endif

#if WF_HAS_EMITTERS
Emitter emitterAt(uint index) {
    uvec4 t = wfTexel(emitterTexels, index);
    return Emitter(t.x, uintBitsToFloat(t.y), uintBitsToFloat(t.z), t.w);
}
#endif

#if WF_HAS_EMITTERS && WF_LIGHT_TREE
LightTreeNode lightTreeNodeAt(uint index) {
    uint base = index * WF_LIGHT_TREE_NODE_TEXELS;
    uvec4 a = wfTexel(lightTreeTexels, base);
    uvec4 b = wfTexel(lightTreeTexels, base + 1u);
    uvec4 c = wfTexel(lightTreeTexels, base + 2u);
    uvec4 d = wfTexel(lightTreeTexels, base + 3u);
    return LightTreeNode(uintBitsToFloat(a.xyz), uintBitsToFloat(a.w), uintBitsToFloat(b.xyz),
                         b.w, uintBitsToFloat(c.xyz), uintBitsToFloat(c.w),
                         uintBitsToFloat(d.x), d.y, 0.0, 0.0);
}

// xy: the emitter's trail from the root, z: 1 if it is in the tree.
uvec4 lightTreeTrailAt(uint emitter) { return wfTexel(lightTreeTrailTexels, emitter); }
#endif

#if WF_HAS_LIGHTS
// As stored; lightAt (motion.glsl) moves a moving one to the ray's time.
PunctualLight lightRecordAt(uint index) {
    uint base = index * WF_PUNCTUAL_LIGHT_TEXELS;
    uvec4 a = wfTexel(lightTexels, base);
    uvec4 b = wfTexel(lightTexels, base + 1u);
    uvec4 c = wfTexel(lightTexels, base + 2u);
    uvec4 d = wfTexel(lightTexels, base + 3u);
    return PunctualLight(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz),
                         uintBitsToFloat(b.w), uintBitsToFloat(c.xyz), uintBitsToFloat(c.w),
                         uintBitsToFloat(d.x), d.y, d.z, uintBitsToFloat(d.w));
}
#endif

#if WF_HAS_ENVIRONMENT
vec3 environmentAt(uint texel) { return uintBitsToFloat(wfTexel(environmentTexels, texel).rgb); }
#if WF_HAS_EMITTERS
Emitter environmentAliasAt(uint index) {
    uvec4 t = wfTexel(environmentAliasTexels, index);
    return Emitter(t.x, uintBitsToFloat(t.y), uintBitsToFloat(t.z), t.w);
}
#endif
#endif
