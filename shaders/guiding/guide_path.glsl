// What a path does with the guide (WF_GUIDING only; includers provide guide_bindings.glsl):
// find the frozen quadtree at a point, keep training records of its guided vertices, take
// each record's "radiance before" when the next vertex is shaded, and splat the radiance that
// arrived after each record once the path is done.

// The spatial node of the leaf holding world point p.
uint guideLeafNode(vec3 p) {
    return guideSpatialLeaf((p - guide.boxLo) * guide.invBoxSize);
}

// The path starts: no records.
void guideStartPath(uint path) {
    if (guide.training != 0u)
        guideCounts[path] = 0u;
}

// Before a vertex adds its emission: the previous guided vertex's own light (its NEE) is in
// the path's radiance by now, and nothing that arrived along its sampled direction is yet.
void guideTakeRadianceBefore(uint path, vec3 pathRadiance) {
    if (guide.training == 0u)
        return;
    uint count = guideCounts[path];
    if (count == 0u)
        return;
    uint slot = path * WF_GUIDE_RECORDS + count - 1u;
    if (guideRecords[slot].pending != 0u) {
        guideRecords[slot].radianceBefore = pathRadiance;
        guideRecords[slot].pending = 0u;
    }
}

// A guided vertex at p chose direction wi with mixture pdf `pdf`, leaving throughput beta.
void guideKeepRecord(uint path, vec3 p, vec3 wi, float pdf, vec3 beta) {
    if (guide.training == 0u)
        return;
    uint count = guideCounts[path];
    if (count >= WF_GUIDE_RECORDS || !(pdf > 0.0))
        return;
    GuideRecord r;
    r.position = p;
    r.pending = 1u;
    r.direction = wi;
    r.pad0 = 0.0;
    r.scale = vec3(beta.r > 0.0 ? 1.0 / (beta.r * pdf) : 0.0,
                   beta.g > 0.0 ? 1.0 / (beta.g * pdf) : 0.0,
                   beta.b > 0.0 ? 1.0 / (beta.b * pdf) : 0.0);
    r.pad1 = 0.0;
    r.radianceBefore = vec3(0.0);
    r.pad2 = 0.0;
    guideRecords[path * WF_GUIDE_RECORDS + count] = r;
    guideCounts[path] = count + 1u;
}

// Adds value (>= 0) to a building cell: 64-bit fixed point in two words, the carry added by
// hand, so the sums do not depend on the order of the atomics.
void guideAddFixed(uint cell, float value) {
    uint add = uint(min(value, WF_GUIDE_MAX_SPLAT) * WF_GUIDE_FIXED_SCALE);
    if (add == 0u)
        return;
    uint old = atomicAdd(guideSplats[2u * cell], add);
    if (old + add < old)
        atomicAdd(guideSplats[2u * cell + 1u], 1u);
}

// The path is done (its radiance final): every record with its radiance before taken splats
// the radiance that arrived after it.
void guideSplatPath(uint path, vec3 pathRadiance) {
    if (guide.training == 0u)
        return;
    uint count = min(guideCounts[path], WF_GUIDE_RECORDS);
    for (uint k = 0u; k < count; ++k) {
        GuideRecord r = guideRecords[path * WF_GUIDE_RECORDS + k];
        if (r.pending != 0u)
            continue;
        vec3 after = max(pathRadiance - r.radianceBefore, vec3(0.0)) * r.scale;
        float value = (after.r + after.g + after.b) * (1.0 / 3.0);
        uint node = guideLeafNode(r.position);
        atomicAdd(guideLeafSamples[guideSpatial[node].child & ~WF_GUIDE_LEAF], 1u);
        if (value > 0.0 && !isinf(value) && !isnan(value))
            guideAddFixed(guideBuildingCell(guideSpatial[node].buildingRoot,
                                            guideDirToSquare(r.direction)),
                          value);
    }
}
