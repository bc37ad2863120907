// The scene tables every ray and shading point reads at scattered indices, bound as RGBA32UI
// storage texel buffers read with imageLoad (src/gpu/compute_program.h says why) and unpacked
// into the structs of scene_types.h. Unused fields cost nothing: the compiler drops loads whose
// texel is unread.
layout(binding = WF_BINDING_TRIANGLES, rgba32ui) uniform readonly restrict uimageBuffer
    triangleTexels;
layout(binding = WF_BINDING_BVH_NODES, rgba32ui) uniform readonly restrict uimageBuffer
    bvhNodeTexels;
layout(binding = WF_BINDING_MATERIALS, rgba32ui) uniform readonly restrict uimageBuffer
    materialTexels;
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
    uint base = index * WF_TRIANGLE_TEXELS;
    uvec4 a = wfTexel(triangleTexels, base);
    uvec4 b = wfTexel(triangleTexels, base + 1u);
    uvec4 c = wfTexel(triangleTexels, base + 2u);
    return Triangle(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w,
                    uintBitsToFloat(c.xyz), c.w);
}

BvhPair bvhPairAt(uint index) {
    uint base = index * WF_BVH_PAIR_TEXELS;
    uvec4 a = wfTexel(bvhNodeTexels, base);
    uvec4 b = wfTexel(bvhNodeTexels, base + 1u);
    uvec4 c = wfTexel(bvhNodeTexels, base + 2u);
    uvec4 d = wfTexel(bvhNodeTexels, base + 3u);
    return BvhPair(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz), b.w,
                   uintBitsToFloat(c.xyz), c.w, uintBitsToFloat(d.xyz), d.w);
}

Material materialAt(uint index) {
    uint base = index * WF_MATERIAL_TEXELS;
    uvec4 t0 = wfTexel(materialTexels, base);
    uvec4 t1 = wfTexel(materialTexels, base + 1u);
    uvec4 t2 = wfTexel(materialTexels, base + 2u);
    uvec4 t3 = wfTexel(materialTexels, base + 3u);
    uvec4 t4 = wfTexel(materialTexels, base + 4u);
    uvec4 t5 = wfTexel(materialTexels, base + 5u);
    return Material(uintBitsToFloat(t0), uintBitsToFloat(t1.xyz), t1.w, uintBitsToFloat(t2.x),
                    uintBitsToFloat(t2.y), uintBitsToFloat(t2.z), uintBitsToFloat(t2.w),
                    uintBitsToFloat(t3.xyz), uintBitsToFloat(t3.w), uintBitsToFloat(t4.x),
                    uintBitsToFloat(t4.y), t4.z, t4.w, t5.x, t5.y, t5.z, t5.w);
}

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
PunctualLight lightAt(uint index) {
    uint base = index * WF_PUNCTUAL_LIGHT_TEXELS;
    uvec4 a = wfTexel(lightTexels, base);
    uvec4 b = wfTexel(lightTexels, base + 1u);
    uvec4 c = wfTexel(lightTexels, base + 2u);
    uvec4 d = wfTexel(lightTexels, base + 3u);
    return PunctualLight(uintBitsToFloat(a.xyz), a.w, uintBitsToFloat(b.xyz),
                         uintBitsToFloat(b.w), uintBitsToFloat(c.xyz), uintBitsToFloat(c.w),
                         uintBitsToFloat(d.x), d.y, uintBitsToFloat(d.z), uintBitsToFloat(d.w));
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
