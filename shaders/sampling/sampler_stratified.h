// `stratified` and `multijitter`: finite sets of N = set size samples per pixel (the render's
// total, so that a render in any number of waves or --spp-offset parts is one set). A 1D
// dimension has N strata; a 2D pair a grid of nx x ny >= N cells, nx = ceil(sqrt(N)).
//   stratified:  jittered sampling; sample i takes cell permute(i) of the grid, a random
//                permutation per (pixel, dimension pair, seed), and a uniform point inside it.
//   multijitter: correlated multi-jittered sampling (Kensler 2013): stratified in the grid and
//                in both 1D projections (N x 1 and 1 x N strata), with the sub-cell positions
//                shuffled by one permutation per row and one per column.
// When N < nx * ny the set uses N of the cells; the final random rotation of permuteIndex
// makes every cell equally likely, so the estimate stays unbiased. Samples past N repeat the
// set with fresh randomization. Without randomization every pixel uses the same set, cells in
// a fixed order, points at the cell centres (stratified) or unjittered (multijitter).
#ifndef WF_SAMPLER_STRATIFIED_H
#define WF_SAMPLER_STRATIFIED_H

#include "sampling/sampler_common.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// Columns of the grid of a 2D set of n samples: the smallest c with c * c >= n.
WF_INLINE uint stratifiedGridWidth(uint n) {
    uint c = uint(ceil(sqrt(float(n))));
    while (c * c < n)
        ++c;
    while (c > 1u && (c - 1u) * (c - 1u) >= n)
        --c;
    return max(c, 1u);
}

// Per-set keys (x: cell order, y, z: row and column shuffles) and per-sample jitter (w, and the
// next dimension's in the second call). A repetition of the set gets keys of its own.
WF_INLINE uvec4 stratifiedKeys(uint pixel, uint dimension, uint seed, uint repetition,
                               bool randomize) {
    return randomize ? samplerKeys(pixel, dimension, seed + repetition * 0x9e3779b9u)
                     : samplerKeys(0u, dimension, 0u);
}

WF_INLINE vec2 stratifiedJitter(uint pixel, uint sampleIndex, uint dimension, uint seed,
                                bool randomize) {
    if (!randomize)
        return vec2(0.5f);
    uvec4 h = pcg4d(uvec4(pixel, sampleIndex, dimension, seed));
    return vec2(uintToUnitFloat(h.x), uintToUnitFloat(h.y));
}

// 1D: N strata, both samplers (a 1D multi-jittered set is a jittered one).
WF_INLINE float stratifiedSample1D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                                   uint setSize, bool randomize) {
    uint n = max(setSize, 1u);
    uvec2 at = setIndex(sampleIndex, n);
    uvec4 key = stratifiedKeys(pixel, dimension, seed, at.y, randomize);
    uint stratum = randomize ? permuteIndex(at.x, n, key.x) : at.x;
    float jitter = stratifiedJitter(pixel, sampleIndex, dimension, seed, randomize).x;
    return min((float(stratum) + jitter) / float(n), WF_ONE_MINUS_EPSILON);
}

WF_INLINE vec2 stratifiedSample2D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                                  uint setSize, bool randomize) {
    uint n = max(setSize, 1u);
    uint nx = stratifiedGridWidth(n);
    uint ny = (n + nx - 1u) / nx;
    uvec2 at = setIndex(sampleIndex, n);
    uvec4 key = stratifiedKeys(pixel, dimension, seed, at.y, randomize);
    uint cell = randomize ? permuteIndex(at.x, nx * ny, key.x) : at.x;
    vec2 jitter = stratifiedJitter(pixel, sampleIndex, dimension, seed, randomize);
    return min((vec2(float(cell % nx), float(cell / nx)) + jitter) / vec2(float(nx), float(ny)),
               vec2(WF_ONE_MINUS_EPSILON));
}

// Kensler's correlated multi-jittered set: cell (column c, row r) of an m x n grid holds its
// point at sub-position (permuted row r, permuted column c), so every column and every row
// of the fine N x N lattice holds one point (for N = m * n).
WF_INLINE vec2 multijitterSample2D(uint pixel, uint sampleIndex, uint dimension, uint seed,
                                   uint setSize, bool randomize) {
    uint n = max(setSize, 1u);
    uint columns = stratifiedGridWidth(n);
    uint rows = (n + columns - 1u) / columns;
    uvec2 at = setIndex(sampleIndex, n);
    uvec4 key = stratifiedKeys(pixel, dimension, seed, at.y, randomize);
    uint cell = randomize ? permuteIndex(at.x, columns * rows, key.x) : at.x;
    uint column = cell % columns;
    uint row = cell / columns;
    uint subRow = randomize ? permuteIndex(row, rows, key.y) : row;
    uint subColumn = randomize ? permuteIndex(column, columns, key.z) : column;
    vec2 jitter = stratifiedJitter(pixel, sampleIndex, dimension, seed, randomize);
    float x = (float(column) + (float(subRow) + jitter.x) / float(rows)) / float(columns);
    float y = (float(row) + (float(subColumn) + jitter.y) / float(columns)) / float(rows);
    return min(vec2(x, y), vec2(WF_ONE_MINUS_EPSILON));
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
