// Vertex merging (--integrator vcm): a camera vertex gathers the light vertices of its own
// sample index within that index's radius (vcm_grid.glsl), each a photon density estimate
// weighed among every strategy that makes the path (vcm_mis.h's merge weight). Included by
// bdpt_connect.glsl; shade.comp adds the sum to the path's light film entry. Consistent, not
// unbiased: a merge blurs the light over the radius, which shrinks with the sample index.
#ifndef WF_VCM_MERGE_GLSL
#define WF_VCM_MERGE_GLSL
#include "bidir/light_film.glsl"

#define WF_VCM_QUERY_BOUND 0.1
// An independent random number per camera vertex for the query's roulette, off the sampler's
// dimensions (rng.h numbers those from 0 up), so that vcm's other samples stay as bdpt's.
#define WF_DIM_MERGE_ROULETTE 0x40000000u

// The light vertices one query gathers before it evaluates them (vcmMergeBatch). In 8 to 16
// lanes a list walk runs as long as its longest list, and about one photon in five that a walk
// passes lies within the radius, so a walk that evaluated each in place ran the merge's
// evaluation (the camera's BSDF, its two pdfs, the MIS weight) on nearly every step of some
// lane; gathering first runs it as often as the lane with the most merges needs.
#define WF_VCM_BATCH 16u

// The merges of camera vertex c with light vertex slots candidates[0 .. count), into sum.
void vcmMergeBatch(BdptCameraVertex c, VcmMisConfig cfg, float normalization,
                   uint candidates[WF_VCM_BATCH], uint count, inout LightFilmSum sum) {
    for (uint k = 0u; k < count; ++k) {
        uint slot = candidates[k];
        vec4 lightDirection = lightVertexDirections[slot];
        vec4 lightThroughput = lightVertexThroughputs[slot];
        vec3 toLight = lightDirection.xyz;
        vec3 wi = vec3(dot(toLight, c.tangent), dot(toLight, c.bitangent), dot(toLight, c.n));
        float cosGeometric = abs(dot(toLight, c.ng));
        if (!(cosGeometric > 0.0))
            continue;
        vec3 f = bdptEval(WF_BDPT_LOBES(c.bsdf, c.layers), c.woLocal, wi);
        if (all(equal(f, vec3(0.0))))
            continue;
        VcmSubpathMis lightMis;
        lightMis.dVCM = lightDirection.w;
        lightMis.dVC = lightThroughput.w;
        lightMis.dVM = lightVertexPositions[slot].w;
        float weight = vcmWeightMerge(
            cfg, c.mis, lightMis, bdptPdf(WF_BDPT_LOBES(c.bsdf, c.layers), c.woLocal, wi),
            bdptPdf(WF_BDPT_LOBES(c.bsdf, c.layers), wi, c.woLocal));
        // The photons arrive per unit of geometric area; the BSDF integrates against the
        // shading normal's cosine (both 1 where the two normals agree).
        vec3 value = clampContribution(c.beta * f * lightThroughput.rgb *
                                       (weight * normalization * abs(wi.z) / cosGeometric));
        bool storable = all(greaterThanEqual(value, vec3(0.0))) &&
                        all(lessThanEqual(value, vec3(WF_LIGHT_FILM_MAX)));
        if (storable)
            lightFilmSumAdd(sum, value);
        else
            atomicAdd(counters.nonFiniteSamples, 1u);
    }
}

// The merges of camera vertex c at camera bounce `depth` of `path` (of a wave of
// `wavePixels` pixels per sample slot), summed in the light film's fixed point (so their order
// does not matter). Merges over WF_LIGHT_FILM_MAX or not
// finite are dropped and counted with the NaN samples.
LightFilmSum vcmMerge(BdptCameraVertex c, uint path, uint depth, uint wavePixels) {
    LightFilmSum sum = lightFilmSumZero();
    if (!c.connectable || depth + 2u > params.maxDepth)
        return sum;
    float radius = vcmMergeRadius(c.sampleIndex);
    float radiusSq = radius * radius;
    VcmMisConfig cfg = bdptMisConfig(c.sampleIndex);
    // A photon's flux is its throughput over the light subpaths of the sample index; the
    // estimate divides it by the disk it is gathered over.
    float normalization = 1.0 / (WF_PI * radiusSq * float(params.lightPaths));
    // Russian roulette on the query, unbiased (taken with probability q, it counts 1 / q). Its
    // merges weigh at most vcmMergeWeightBound; below WF_VCM_QUERY_BOUND the query is taken with
    // probability bound / WF_VCM_QUERY_BOUND, so a merge's value grows to at most
    // WF_VCM_QUERY_BOUND times its unweighted estimate. Camera vertices that connect far better
    // than they merge (most of a diffuse scene's) made most of merging's time for a few tenths
    // of a percent of the image (docs/bidirectional.md).
    float queryProbability =
        min(1.0, vcmMergeWeightBound(cfg, c.mis) * (1.0 / WF_VCM_QUERY_BOUND));
    if (queryProbability < 1.0 &&
        independentSample1D(c.pixel, c.sampleIndex, WF_DIM_MERGE_ROULETTE + depth,
                            params.seed) >= queryProbability)
        return sum;
    normalization /= queryProbability;
    uint firstPath = path / wavePixels * wavePixels; // the first path of its sample slot
    uint lastSlot = (params.maxDepth - depth - 1u) * params.pathCapacity;
    ivec3 low = vcmCell(c.p - vec3(radius), 2.0 * radius);
    uint visited[8];
    uint visitedCount = 0u;
    uint candidates[WF_VCM_BATCH];
    uint candidateCount = 0u;
    for (uint corner = 0u; corner < 8u; ++corner) {
        ivec3 cell = low + ivec3(corner & 1u, (corner >> 1u) & 1u, corner >> 2u);
        uint bucket = vcmBucket(cell, c.sampleIndex);
        // Two cells may share a bucket: read each list once, or its photons count twice.
        bool seen = false;
        for (uint i = 0u; i < visitedCount; ++i)
            seen = seen || visited[i] == bucket;
        if (seen)
            continue;
        visited[visitedCount++] = bucket;
        for (uint slot = mergeLists[bucket]; slot != WF_VCM_END;
             slot = mergeLists[params.mergeCells + slot]) {
            vec3 offset = lightVertexPositions[slot].xyz - c.p;
            if (dot(offset, offset) > radiusSq)
                continue;
            // Buckets hold other cells and other sample indices too; slot = light bounce *
            // pathCapacity + path, and bounce d merges as a path of depth + d + 2 segments.
            if (slot >= lastSlot || slot % params.pathCapacity - firstPath >= wavePixels)
                continue;
            candidates[candidateCount++] = slot;
            if (candidateCount == WF_VCM_BATCH) {
                vcmMergeBatch(c, cfg, normalization, candidates, candidateCount, sum);
                candidateCount = 0u;
            }
        }
    }
    vcmMergeBatch(c, cfg, normalization, candidates, candidateCount, sum);
    return sum;
}

#endif
