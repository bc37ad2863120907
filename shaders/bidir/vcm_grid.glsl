// Vertex merging's hash grid (--integrator vcm, issue 46): light_shade inserts each non-Dirac
// light vertex it keeps (bdpt_state.glsl) into the list of its grid cell as it finds it, and
// camera vertices gather the vertices within the merging radius (vcm_merge.glsl).
//
// Sample index i of the render is VCM's iteration i + 1: it merges with its own light
// subpaths only (one per pixel, as bdpt connects them), at radius r_i = r_0 (i + 1)^((alpha -
// 1) / 2) with alpha = 0.75 (Knaus and Zwicker's progressive schedule, as Georgiev's VCM), so
// the bias vanishes as the samples grow while each sample stays independent of the others
// (the film's error estimate rests on that). One grid holds the whole wave: the cell key
// carries the sample index, and each cell's size is 2 r_i, so a query reads at most 8 cells.
// Lists are built by atomic exchanges, in no fixed order: merges sum in the light film's
// fixed point (light_film.glsl), so the same seed still gives the same image bit for bit.
#ifndef WF_VCM_GRID_GLSL
#define WF_VCM_GRID_GLSL

#define WF_VCM_ALPHA 0.75
#define WF_VCM_END 0xffffffffu

layout(std430, binding = WF_BINDING_LIGHT_VERTEX_POSITIONS) buffer LightVertexPositionBuffer {
    vec4 lightVertexPositions[]; // per light vertex slot (bdpt_state.glsl): its position, dVM
};
layout(std430, binding = WF_BINDING_MERGE_LISTS) buffer MergeListBuffer {
    // [0, mergeCells): per cell of the hash, its list's first vertex slot (WF_VCM_END: none;
    // the host clears them per wave); then per light vertex slot, the next one in its list.
    uint mergeLists[];
};

float vcmMergeRadius(uint sampleIndex) {
    return params.mergeRadius * pow(float(sampleIndex + 1u), 0.5 * (WF_VCM_ALPHA - 1.0));
}

ivec3 vcmCell(vec3 p, float cellSize) {
    return ivec3(floor((p - params.sceneCenter) / cellSize));
}

uint vcmHashStep(uint h, int coordinate) {
    h ^= uint(coordinate) + 0x7F4A7C15u + (h << 6) + (h >> 2);
    h *= 0x85EBCA6Bu;
    return h ^ (h >> 13);
}

uint vcmBucket(ivec3 cell, uint sampleIndex) {
    // Each coordinate through a multiply-xorshift round, so that neighbouring cells and
    // sample indices spread over the whole table.
    uint h = vcmHashStep(vcmHashStep(vcmHashStep(sampleIndex * 0x9E3779B9u, cell.x), cell.y),
                         cell.z);
    return h & (params.mergeCells - 1u);
}

void vcmInsertLightVertex(uint slot, vec3 p, float dVM, uint sampleIndex) {
    uint bucket = vcmBucket(vcmCell(p, 2.0 * vcmMergeRadius(sampleIndex)), sampleIndex);
    mergeLists[params.mergeCells + slot] = atomicExchange(mergeLists[bucket], slot);
    lightVertexPositions[slot] = vec4(p, dVM);
}

#endif
