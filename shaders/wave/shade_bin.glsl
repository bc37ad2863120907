// The shade bin of a hit (WF_SHADE_BINS > 1), shared by the compute and the ray-traced
// intersect passes. Needs wave/bindings.glsl.
#ifndef WF_SHADE_BIN_GLSL
#define WF_SHADE_BIN_GLSL

// The bin rides in the material's flags (WF_MATERIAL_SHADE_BIN_SHIFT), texel 1 of its entry.
uint shadeBinOf(uvec4 hit) {
    if (hit.w == WF_MISS || (hit.w & WF_SPHERE_HIT) != 0u)
        return WF_LIGHT_HIT_BIN;
    uint material = triangleTexel(hit.w, 0u).w;
    uint flags = wfTexel(materialTexels,
                         WF_MATERIAL_TABLE_START + material * WF_MATERIAL_TEXELS + 1u).w;
    return (flags >> WF_MATERIAL_SHADE_BIN_SHIFT) & WF_MATERIAL_SHADE_BIN_MASK;
}

#endif
