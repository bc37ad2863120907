// The path guide's flattened SD-tree (Mueller et al. 2017), as the GPU reads and writes it.
// One spatial binary tree over the scene's bounds (children split their parent in half along
// x, y, z in turn by depth); each leaf names two directional quadtrees over the square
// ((cos theta + 1) / 2, phi / 2 pi) of world directions (an area-preserving map, so a
// square pdf is a sphere pdf times 4 pi): the frozen one sampled this iteration, and the one
// being built from this iteration's splats. Built and rebuilt on the host
// (src/render/guiding/sd_tree.cpp); sampled by shaders/guiding/guide_tree.h.
#ifndef WF_GUIDE_TYPES_H
#define WF_GUIDE_TYPES_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// GuideSpatialNode.child: a leaf holds its leaf index (into the sample counters).
#define WF_GUIDE_LEAF 0x80000000u
// Depth limits: the walks are bounded loops. 48 spatial levels halve a box 16 times per
// axis; 20 quadtree levels resolve a ~1e-6 share of the sphere.
#define WF_GUIDE_MAX_SPATIAL_DEPTH 48u
#define WF_GUIDE_MAX_DIR_DEPTH 20u
// Splats are 64-bit fixed point (two uints: low word, high word, carried by hand) so that
// the sums do not depend on the order of the atomics: a seed gives one image per device.
// One unit of splatted value is 2^20; a single splat is clamped below 2^32 (value 4096).
#define WF_GUIDE_FIXED_SCALE 1048576.0f
#define WF_GUIDE_MAX_SPLAT 4095.0f

struct GuideSpatialNode {
    uint child;         // interior: the first child (the second is child + 1); leaf: LEAF | leaf
    uint samplingRoot;  // leaf: root of its frozen quadtree in the sampling node array
    uint buildingRoot;  // leaf: root of its quadtree under construction in the building array
    float bsdfFraction; // leaf: its learnt share of BSDF sampling; 0: GuideParams.bsdfFraction
    // Parallax (leaf): the frozen quadtree holds directions seen from samplingCentre to
    // radiance placed radianceDistance away (learnt; 0: directions are used as they are);
    // the building quadtree's splats are directions seen from buildingCentre (the mean
    // position of the leaf's records in the iteration before, or its box's centre).
    vec3 samplingCentre;
    float radianceDistance;
    vec3 buildingCentre;
    float spatialPad;
};

// The learnt BSDF fraction: each training record also adds, for each candidate share j,
// its estimator's second moment had the vertex sampled with share j (reweighted from the share
// it used); the host picks the candidate with the least (src/render/guiding/sd_tree.cpp).
// Per leaf the counters hold the record count, then per candidate a 64-bit fixed-point sum
// (low word, high word) in units of 1 / WF_GUIDE_MOMENT_SCALE, each term clamped at
// WF_GUIDE_MAX_MOMENT (the choice only: the image stays unbiased whatever share is chosen).
#define WF_GUIDE_FRACTIONS 6u
// Then, for parallax, more 64-bit sums: splatted value x distance from the building centre
// to where the record's ray ended, and splatted value (their ratio: the leaf's learnt
// radiance distance); and the records' positions (x, y, z from GuideParams.boxLo: their
// mean is the next iteration's building centre).
#define WF_GUIDE_STAT_DISTANCE (1u + 2u * WF_GUIDE_FRACTIONS)
#define WF_GUIDE_STAT_ENERGY (WF_GUIDE_STAT_DISTANCE + 2u)
#define WF_GUIDE_STAT_POSITION (WF_GUIDE_STAT_ENERGY + 2u)
// Then the records' whole-path estimates' sum of squares and sum (the learnt share weighs what a
// candidate removes against their variance): per record w = f |cos| x scale x the path's final
// radiance, the path's estimate at the vertex with everything before it divided by the
// throughput to it (at the camera's vertex, the pixel sample itself).
#define WF_GUIDE_STAT_TOTAL (WF_GUIDE_STAT_POSITION + 6u)
#define WF_GUIDE_STAT_TOTAL_SUM (WF_GUIDE_STAT_TOTAL + 2u)
#define WF_GUIDE_LEAF_STATS (WF_GUIDE_STAT_TOTAL_SUM + 2u)
#define WF_GUIDE_MOMENT_SCALE 4096.0f
#define WF_GUIDE_MAX_MOMENT 1.0e9f

// A quadtree node. Quadrant q covers x-half (q & 1), y-half (q >> 1) of the node's square.
// child[q] == 0: quadrant q is a leaf (a root is never anyone's child, so 0 is free).
// prob[q]: the share of the node's energy in quadrant q (sums to 1; uniform where the node
// saw nothing); unused in the building array, whose energy lives in the splat counters.
struct GuideDirNode {
    uvec4 child;
    vec4 prob;
};

// What the passes need beside the trees (one storage buffer, WF_BINDING_GUIDE_PARAMS).
struct GuideParams {
    vec3 boxLo;         // the spatial tree's (cubic) box
    float bsdfFraction; // share of BSDF sampling in the one-sample mixture
    vec3 invBoxSize;
    uint training;      // 1: keep training records and splat them into the building tree
    uint maxDepth;      // guide only vertices of bounce index below this (0: none)
    uint learnFraction; // 1: training records add the second moments of the candidate shares
    uint parallax;      // 1: splat directions as seen from the leaf's centre (see GuideSpatialNode)
    float farDistance;  // where a record whose ray left the scene places its radiance
};

// A guided vertex of a path, kept until the path ends (WF_GUIDE_RECORDS per path): the
// radiance that reaches the camera after it, (path radiance at the end - radianceBefore) x
// scale, is the incident radiance along `direction` divided by the mixture pdf that chose it,
// which is what the building quadtree sums.
struct GuideRecord {
    vec3 position;
    float hitDistance;   // < 0: radianceBefore not yet taken (the next shade pass takes it);
                         // then 0 until that pass finds the surface the ray hit, its distance
    vec3 direction;
    float bsdfPdf;       // the BSDF's density of `direction` (solid angle)
    vec3 scale;          // per channel 1 / (throughput after the bounce x mixture pdf); 0 if none
    float guidePdf;      // the guide's density of `direction` (solid angle)
    vec3 radianceBefore; // the path's radiance once this vertex's own light (NEE) was in
    float fCos;          // the BSDF value (mean over channels) x |cos| for `direction`
};
#define WF_GUIDE_RECORDS 4u

#define WF_GUIDE_SPATIAL_NODE_TEXELS 3u
#define WF_GUIDE_DIR_NODE_TEXELS 2u

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::GuideSpatialNode) == 16 * WF_GUIDE_SPATIAL_NODE_TEXELS);
static_assert(offsetof(wf::gpu_types::GuideSpatialNode, samplingCentre) == 16);
static_assert(offsetof(wf::gpu_types::GuideSpatialNode, buildingCentre) == 32);
static_assert(sizeof(wf::gpu_types::GuideDirNode) == 16 * WF_GUIDE_DIR_NODE_TEXELS);
static_assert(offsetof(wf::gpu_types::GuideDirNode, prob) == 16);
static_assert(sizeof(wf::gpu_types::GuideParams) == 48);
static_assert(offsetof(wf::gpu_types::GuideParams, maxDepth) == 32);
static_assert(offsetof(wf::gpu_types::GuideParams, invBoxSize) == 16);
static_assert(sizeof(wf::gpu_types::GuideRecord) == 64);
static_assert(offsetof(wf::gpu_types::GuideRecord, direction) == 16);
static_assert(offsetof(wf::gpu_types::GuideRecord, scale) == 32);
static_assert(offsetof(wf::gpu_types::GuideRecord, radianceBefore) == 48);
#endif

#endif
