// What a path does with the guide (WF_GUIDING only; includers provide guide_bindings.glsl):
// find the frozen quadtree at a point, keep training records of its guided vertices, take
// each record's "radiance before" when the next vertex is shaded, and splat the radiance that
// arrived after each record once the path is done.

// The spatial node of the leaf holding world point p.
uint guideLeafNode(vec3 p) {
    return guideSpatialLeaf((p - guide.boxLo) * guide.invBoxSize);
}

// The BSDF's share of the mixture at the leaf of spatial node `node`: learnt, or the default.
float guideLeafFraction(uint node) {
    float learnt = guideSpatial[node].bsdfFraction;
    return learnt > 0.0 ? learnt : guide.bsdfFraction;
}

// A path's word in guideCounts: how many records it keeps, and what its latest record still
// waits for, so that the path's later vertices read this word alone, not the record.
#define WF_GUIDE_COUNT_MASK 0xffu
#define WF_GUIDE_AWAITS_RADIANCE 0x100u // its radiance before: the next shade pass takes it
#define WF_GUIDE_AWAITS_HIT 0x200u      // then the point its ray hit, if any

// The path starts: no records.
void guideStartPath(uint path) {
    if (guide.training != 0u)
        guideCounts[path] = 0u;
}

// The slot of record k of a path: records of one index lie together, path after path, so that
// the lanes of a SIMD group (consecutive paths) touch neighbouring records and most paths'
// only record (the camera's vertex) spans a quarter of the buffer: in path-major order every
// access of a wave's records was a TLB miss in a buffer of 2^19 x 256 bytes.
uint guideRecordSlot(uint path, uint k) {
    return k * params.pathCapacity + path;
}

// The slot of the path's latest training record, given the path's word (a count >= 1).
uint guideLatestSlot(uint path, uint word) {
    return guideRecordSlot(path, (word & WF_GUIDE_COUNT_MASK) - 1u);
}

// Before a vertex adds its emission: the previous guided vertex's own light (its NEE) is in
// the path's radiance by now, and nothing that arrived along its sampled direction is yet.
void guideTakeRadianceBefore(uint path, vec3 pathRadiance) {
    if (guide.training == 0u)
        return;
    uint word = guideCounts[path];
    if ((word & WF_GUIDE_AWAITS_RADIANCE) != 0u) {
        uint slot = guideLatestSlot(path, word);
        guideRecords[slot].radianceBefore = pathRadiance;
        guideRecords[slot].hitDistance = 0.0; // a ray that left the scene keeps 0
        guideCounts[path] = (word & WF_GUIDE_COUNT_MASK) | WF_GUIDE_AWAITS_HIT;
    }
}

// The vertex just shaded lies at p: the record whose ray found it (its radiance before just
// taken) keeps how far its radiance came from.
void guideTakeHitPoint(uint path, vec3 p) {
    if (guide.training == 0u)
        return;
    uint word = guideCounts[path];
    if ((word & WF_GUIDE_AWAITS_HIT) != 0u) {
        uint slot = guideLatestSlot(path, word);
        guideRecords[slot].hitDistance = max(length(p - guideRecords[slot].position), 1e-6);
        guideCounts[path] = word & WF_GUIDE_COUNT_MASK;
    }
}

// What the guide at spatial node `node` needs at a vertex at p: the vertex's offset from the
// leaf's sampling centre and the parallax radius (0: none).
void guideParallaxAt(uint node, vec3 p, out vec3 offset, out float radius) {
    offset = p - guideSpatial[node].samplingCentre;
    radius = guideParallaxRadius(offset, guideSpatial[node].radianceDistance);
}

// A guided vertex at p chose direction wi with mixture pdf `pdf`, leaving throughput beta;
// bsdfPdf and guidePdf: the mixture's two densities there, fCos: f |cos| (channel mean).
void guideKeepRecord(uint path, vec3 p, vec3 wi, float pdf, vec3 beta, float bsdfPdf,
                     float guidePdf, float fCos) {
    if (guide.training == 0u)
        return;
    uint count = guideCounts[path] & WF_GUIDE_COUNT_MASK;
    if (count >= WF_GUIDE_RECORDS || !(pdf > 0.0))
        return;
    GuideRecord r;
    r.position = p;
    r.hitDistance = -1.0;
    r.direction = wi;
    r.bsdfPdf = bsdfPdf;
    r.scale = vec3(beta.r > 0.0 ? 1.0 / (beta.r * pdf) : 0.0,
                   beta.g > 0.0 ? 1.0 / (beta.g * pdf) : 0.0,
                   beta.b > 0.0 ? 1.0 / (beta.b * pdf) : 0.0);
    r.guidePdf = guidePdf;
    r.radianceBefore = vec3(0.0);
    r.fCos = fCos;
    guideRecords[guideRecordSlot(path, count)] = r;
    guideCounts[path] = (count + 1u) | WF_GUIDE_AWAITS_RADIANCE;
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

// Adds value (>= 0, clamped at WF_GUIDE_MAX_MOMENT) to a leaf's 64-bit fixed-point moment
// (two words at `index`): the low word's carry by hand, the high word for what exceeds it.
void guideAddMoment(uint index, float value) {
    float v = min(value, WF_GUIDE_MAX_MOMENT) * WF_GUIDE_MOMENT_SCALE;
    uint high = uint(v * (1.0 / 4294967296.0));
    uint low = uint(max(v - float(high) * 4294967296.0, 0.0));
    if (low != 0u) {
        uint old = atomicAdd(guideLeafSamples[index], low);
        if (old + low < old)
            high += 1u;
    }
    if (high != 0u)
        atomicAdd(guideLeafSamples[index + 1u], high);
}

// The path is done (its radiance final): every record with its radiance before taken splats
// the radiance that arrived after it.
void guideSplatPath(uint path, vec3 pathRadiance) {
    if (guide.training == 0u)
        return;
    uint count = min(guideCounts[path] & WF_GUIDE_COUNT_MASK, WF_GUIDE_RECORDS);
    for (uint k = 0u; k < count; ++k) {
        GuideRecord r = guideRecords[guideRecordSlot(path, k)];
        if (r.hitDistance < 0.0)
            continue;
        vec3 after = max(pathRadiance - r.radianceBefore, vec3(0.0)) * r.scale;
        float value = (after.r + after.g + after.b) * (1.0 / 3.0);
        uint node = guideLeafNode(r.position);
        uint stats = (guideSpatial[node].child & ~WF_GUIDE_LEAF) * WF_GUIDE_LEAF_STATS;
        atomicAdd(guideLeafSamples[stats], 1u);
        if (guide.parallax != 0u) {
            vec3 inBox = max(r.position - guide.boxLo, vec3(0.0));
            guideAddMoment(stats + WF_GUIDE_STAT_POSITION, inBox.x);
            guideAddMoment(stats + WF_GUIDE_STAT_POSITION + 2u, inBox.y);
            guideAddMoment(stats + WF_GUIDE_STAT_POSITION + 4u, inBox.z);
        }
        if (guide.learnFraction != 0u) {
            vec3 total = max(pathRadiance, vec3(0.0)) * r.scale;
            float whole = r.fCos * (total.r + total.g + total.b) * (1.0 / 3.0);
            if (whole > 0.0 && !isinf(whole)) {
                guideAddMoment(stats + WF_GUIDE_STAT_TOTAL, whole * whole);
                guideAddMoment(stats + WF_GUIDE_STAT_TOTAL_SUM, whole);
            }
        }
        if (!(value > 0.0) || isinf(value))
            continue;
        vec3 direction = r.direction;
        if (guide.parallax != 0u) {
            // The direction from the leaf's centre to where the radiance came from (a ray that
            // left the scene: from far away), and how far that is, for the leaf's distance.
            vec3 source = r.position + r.direction * (r.hitDistance > 0.0 ? r.hitDistance
                                                                          : guide.farDistance);
            vec3 fromCentre = source - guideSpatial[node].buildingCentre;
            float distance = length(fromCentre);
            if (distance > 0.0)
                direction = fromCentre / distance;
            guideAddMoment(stats + WF_GUIDE_STAT_DISTANCE, value * distance);
            guideAddMoment(stats + WF_GUIDE_STAT_ENERGY, value);
        }
        guideAddFixed(guideBuildingCell(guideSpatial[node].buildingRoot,
                                        guideDirToSquare(direction)),
                      value);
        if (guide.learnFraction != 0u) {
            // value is L / p_used; the vertex's estimate is f |cos| L / p_used.
            float estimate = r.fCos * value;
            float used = guideLeafFraction(node);
            for (uint j = 0u; j < WF_GUIDE_FRACTIONS; ++j)
                guideAddMoment(stats + 1u + 2u * j,
                               guideCandidateMoment(estimate, r.bsdfPdf, r.guidePdf, used,
                                                    guideFractionCandidate(j)));
        }
    }
}
