// Render state shared by the host and every pass: binding numbers, per-render parameters, the
// queue counters with their indirect-dispatch arguments, and push constants.
//
// Queue protocol of one wave (see docs/ARCHITECTURE.md):
//   raygen      writes PathState for paths [0, pathCount), rayQueue[0] = identity
//   intersect   reads rayQueue[depth & 1] (count in rayArgs.count), writes hits by queue slot
//   (with WF_SHADE_BINS: intersect also appends each queue slot to the shade bin of the
//   material it hit, kindQueues[bin] (kindCount[bin], group count in kindArgs[bin]); one
//   shade pass per bin reads its bin's slots; queue zeroes the bins for the next bounce)
//   shade       reads rayQueue[depth & 1] + hits; appends to rayQueue[(depth+1) & 1] (rayCount)
//               and to the shadow queue (shadowCount): the connection's shadow* data at its
//               slot, its path in shadowOrigin.w; adds emission to radiance
//   queue       copies rayCount/shadowCount into rayArgs/shadowArgs, zeroes them, keeps stats
//               (totals and per depth: depthRays[depth + 1], depthShadowRays[depth])
//   shadow      reads the shadow queue (count in shadowArgs.count); adds unoccluded NEE to
//               radiance
//   accumulate  adds each pixel's paths into the film, zeroing NaN/Inf samples
// With --integrator light (WF_INTEGRATOR 1) the camera's passes run to depth 0 only (emitters
// seen directly), then light subpaths: light_raygen appends to rayQueue[0]; queue; then per
// light bounce intersect, light_shade (appends the continuation, and camera connections to
// the shadow queue), queue, light_splat (visible connections into the light film); and
// accumulate adds radiance + light film per pixel sample.
#ifndef WF_RENDER_TYPES_H
#define WF_RENDER_TYPES_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
#endif

// Texture filtering by ray cones (ray_cones.glsl): on only in variants with textures, where the
// path state gains each ray's cone.
// Shading split by material kind (src/passes/shade_kinds.h): 0 or 1, one shade pass for every
// hit; more, that many bins, each shaded by its own pass. WF_LIGHT_HIT_BIN takes the misses
// and sphere-light hits.
#ifndef WF_SHADE_BINS
#define WF_SHADE_BINS 0
#endif

#ifndef WF_RAY_CONES
#define WF_RAY_CONES 0
#endif

// The integrator (--integrator): defined by the host only for those other than the path
// tracer, whose shaders stay as they were.
#define WF_INTEGRATOR_PATH 0
#define WF_INTEGRATOR_LIGHT 1
#define WF_INTEGRATOR_BDPT 2 // also --integrator vcm, which adds WF_VCM (bidir/vcm_grid.glsl)
#ifndef WF_INTEGRATOR
#define WF_INTEGRATOR WF_INTEGRATOR_PATH
#endif
#ifndef WF_VCM
#define WF_VCM 0
#endif

// Scene data
#define WF_BINDING_TRIANGLES 0
#define WF_BINDING_BVH_NODES 1
#define WF_BINDING_MATERIALS 2
#define WF_BINDING_EMITTERS 3
#define WF_BINDING_INSTANCES 63 // two-level scenes: Instance texels (scene_types.h)
// Per render
#define WF_BINDING_PARAMS 4
#define WF_BINDING_COUNTERS 5
#define WF_BINDING_FILM 6
// Path state, structure of arrays indexed by path
#define WF_BINDING_RAY_ORIGIN 7
#define WF_BINDING_RAY_DIRECTION 8
#define WF_BINDING_THROUGHPUT 9
#define WF_BINDING_RADIANCE 10
#define WF_BINDING_HITS 11
#define WF_BINDING_SHADOW_ORIGIN 12
#define WF_BINDING_SHADOW_DIRECTION 13
#define WF_BINDING_SHADOW_RADIANCE 14
#define WF_BINDING_RAY_QUEUES 15
// Lights beyond emissive triangles
#define WF_BINDING_LIGHT_TREE 16         // LightTreeNode texels (light_tree.h)
#define WF_BINDING_LIGHT_TREE_TRAILS 33  // uvec4 per emitter: trail bits, in-tree flag
#define WF_BINDING_AOV_PATHS 34 // --aov: per path, the camera ray's first hit (2 vec4)
#define WF_BINDING_AOV_FILM 35  // --aov: per pixel, sums of those (2 vec4)
#define WF_BINDING_MOMENT_FILM 36   // --aov variance, --target-error: per pixel, radiance^2 sums
#define WF_BINDING_ACTIVE_PIXELS 37 // --target-error: the pixels a wave's pixel range lists
#define WF_BINDING_REPLICATE_FILM 130 // --error-replicates K: per pixel, replicates 1 .. K-1's sums
// (not 26: texel pages 1-3 take 26-28, texture_types.h)
#define WF_BINDING_RAY_CONES 38       // WF_RAY_CONES: per path, the ray's cone (ray_cones.glsl)
#define WF_BINDING_RAY_CONE_TEXELS 39 // the same, read as RG32UI texels
#define WF_BINDING_TRIANGLE_PAGE1 49 // pages 1-7 of the triangles (49 .. 55)
#define WF_BINDING_BVH_PAGE1 56      // pages 1-7 of the BVH entries (56 .. 62)
#define WF_BINDING_INSTANCE_PAGE1 64 // pages 1-7 of the instances (64 .. 70)
// 71-98: pages 1-7 of the per-triangle attributes (texture_types.h)
#define WF_BINDING_KIND_QUEUES 99      // WF_SHADE_BINS: per bin, pathCapacity queue slots
#define WF_BINDING_KIND_QUEUE_TEXELS 100 // the same, read as R32UI texels
#define WF_BINDING_TOP_LEVEL 101 // WF_RAY_TRACING: the scene's top-level acceleration structure
// WF_MOTION (motion.glsl): the moving things' keys over the shutter, and each path's time.
#define WF_BINDING_MOTION_KEYS 102 // vec4[]
#define WF_BINDING_RAY_TIME 103    // float per path: its time within the shutter, in [0, 1)
// --integrator light: per (pixel, sample slot) of a wave, the light subpaths' splats as 64-bit
// fixed point, two words (low, high) per channel (bidir/light_film.glsl).
#define WF_BINDING_LIGHT_FILM 104
// --integrator bdpt (bidir/bdpt_state.glsl): per path its subpath's MIS quantities and the
// light bounces its light subpath reached; per light vertex (slot d pathCapacity + path) its
// hit, direction to the light and throughput.
#define WF_BINDING_PATH_MIS 105
#define WF_BINDING_LIGHT_DEPTHS 106
#define WF_BINDING_LIGHT_VERTEX_HITS 107
#define WF_BINDING_LIGHT_VERTEX_DIRECTIONS 108
#define WF_BINDING_LIGHT_VERTEX_THROUGHPUTS 109
// --integrator vcm (bidir/vcm_grid.glsl): per light vertex its position and dVM; the hash
// grid's lists (per cell its first vertex, per vertex the next). After the guide's (120-127):
// 110-117 are the vertex colours' (texture_types.h).
#define WF_BINDING_LIGHT_VERTEX_POSITIONS 128
#define WF_BINDING_MERGE_LISTS 129
// WF_HAS_DISPERSION: per path, the wavelength it carries (nm; 0 while it is still RGB); with
// WF_SPECTRAL_HERO (--spectral hero) its four lanes instead (wave/hero_lanes.glsl).
#define WF_BINDING_PATH_WAVELENGTH 118 // after the vertex colours' pages (110 .. 117)
#ifndef WF_SPECTRAL_HERO
#define WF_SPECTRAL_HERO 0
#endif
// WF_GUIDING (shaders/guiding/guide_bindings.glsl): the path guide's SD-tree and records.
#define WF_BINDING_GUIDE_PARAMS 120   // GuideParams
#define WF_BINDING_GUIDE_SPATIAL 121  // GuideSpatialNode[]
#define WF_BINDING_GUIDE_SAMPLING 122 // GuideDirNode[]: the frozen quadtrees
#define WF_BINDING_GUIDE_BUILDING 123 // GuideDirNode[]: the quadtrees being built
#define WF_BINDING_GUIDE_SPLATS 124   // uint[]: 64-bit fixed-point sums, 2 per building cell
#define WF_BINDING_GUIDE_LEAF_SAMPLES 125 // uint[]: splats per spatial leaf
#define WF_BINDING_GUIDE_RECORDS 126  // GuideRecord[WF_GUIDE_RECORDS per path]
#define WF_BINDING_GUIDE_COUNTS 127   // uint per path: records kept
#define WF_BINDING_LIGHTS 17
#define WF_BINDING_ENVIRONMENT 18       // vec4 radiance per texel
#define WF_BINDING_ENVIRONMENT_ALIAS 19 // Emitter-shaped alias table over texels
// 20-31: per-vertex attributes and textures (only for scenes that use them); 32: sampler tables
// 40-48: the path state again, as texel buffers for reading (path_texels.glsl)
#define WF_BINDING_RAY_ORIGIN_TEXELS 40
#define WF_BINDING_RAY_DIRECTION_TEXELS 41
#define WF_BINDING_THROUGHPUT_TEXELS 42
#define WF_BINDING_RADIANCE_TEXELS 43
#define WF_BINDING_HITS_TEXELS 44
#define WF_BINDING_SHADOW_ORIGIN_TEXELS 45
#define WF_BINDING_SHADOW_DIRECTION_TEXELS 46
#define WF_BINDING_SHADOW_RADIANCE_TEXELS 47
#define WF_BINDING_RAY_QUEUE_TEXELS 48

struct RenderParams {
    vec3 cameraPosition;
    float tanHalfFovY;
    vec3 cameraForward;
    float aspect; // width / height of the image
    vec3 cameraUp;
    uint seed;
    vec3 cameraRight;
    uint maxDepth;      // path segments from the camera (1: emitters seen directly)
    uint width;
    uint height;
    uint pixelCount;
    uint rrDepth;       // Russian roulette from this bounce on
    uint emitterCount;
    uint pathCapacity;  // paths per wave that the buffers hold
    uint sphereLightCount; // lights[0, sphereLightCount) are spheres
    uint environmentEmitter; // the environment's emitter-table entry, or WF_NO_EMITTER
    vec3 sceneCenter;   // bounding sphere of the scene: infinite lights' shadow rays end
    float sceneRadius;  // outside it
    uint environmentWidth;
    uint environmentHeight;
    float minThroughput; // --min-throughput (0: off)
    float clampRadiance; // --clamp (0: off)
    float lensRadius;    // thin lens (WF_THIN_LENS): half the aperture
    float focusDistance; // along cameraForward, to the plane in focus
    float orthoHalfHeight; // > 0: an orthographic camera, half the view's height in scene units
    // WF_MOTION: keys evenly spaced over the shutter, segments + 1 of them per moving thing
    // (motion.glsl); 0 for a still camera, else 1 + its first key (3 vec4 per key).
    uint motionSegments;
    uint cameraMotionKeys;
    // WF_VCM: the merging radius of sample index 0 in scene units (bidir/vcm_grid.glsl), and the
    // hash grid's cells (a power of two).
    float mergeRadius;
    uint mergeCells;
    // Light subpaths per sample index (light, bdpt, vcm): one per --light-share pixels
    // (bidir/light_share.glsl); pixelCount without sharing.
    uint lightPaths;
};

// VkDispatchIndirectCommand followed by the item count the dispatch covers.
struct DispatchArgs {
    uint groupsX;
    uint groupsY;
    uint groupsZ;
    uint count;
};

// VkTraceRaysIndirectCommandKHR (width = the queue's count; height and depth 1) and a pad,
// which ray-traced waves (WF_RAY_TRACING) trace their intersect and shadow passes by.
struct TraceArgs {
    uint width;
    uint height;
    uint depth;
    uint pad;
};

// Shade bins (material kinds, src/passes/shade_kinds.h) the counters have room for.
#define WF_MAX_SHADE_BINS 4

// Per-depth statistics (queue occupancy per bounce) cover this many depths; deeper bounces are
// counted in the last entry, so the entries always sum to the totals.
#define WF_TRACKED_DEPTHS 16

struct QueueCounters {
    uint rayCount;    // live append counter of the next ray queue
    uint shadowCount; // live append counter of the shadow queue
    uint pad0;
    uint pad1;
    DispatchArgs rayArgs;
    DispatchArgs shadowArgs;
    uint extensionRays; // stats for the wave, summed by the queue pass
    uint shadowRays;
    uint nonFiniteSamples;
    uint pad2;
    uint depthRays[WF_TRACKED_DEPTHS];       // rays intersected at each depth (0: camera rays)
    uint depthShadowRays[WF_TRACKED_DEPTHS]; // NEE connections made at each depth
    uint kindCount[WF_MAX_SHADE_BINS];       // WF_SHADE_BINS: append counters of the bins
    // The shade passes' arguments: groupsX raised by intersect's appends (atomicMax), groupsY
    // and groupsZ 1 from the wave's start; count unused (kindCount has it).
    DispatchArgs kindArgs[WF_MAX_SHADE_BINS];
    TraceArgs rayTrace;    // WF_RAY_TRACING: rayArgs.count as trace arguments
    TraceArgs shadowTrace; // and shadowArgs.count
};

// A wave covers pixels [pixelBase, pixelBase + wavePixels) x samples [sampleBase, sampleBase +
// samplesPerPixel): path p is sample sampleBase + p / wavePixels of pixel pixelBase + p %
// wavePixels (wave_paths.glsl). Waves smaller than the image keep a submit short. With
// WF_ADAPTIVE the pixel range indexes the active-pixel list instead of the image.
struct PassConstants {
    uint depth;       // bounce index: the ray segment being processed is depth + 1
    uint sampleBase;  // sample index of the wave's first sample per pixel
    uint pathCount;   // paths in this wave: wavePixels * samplesPerPixel
    uint samplesPerPixel; // samples per pixel in this wave
    uint pixelBase;   // first pixel of the wave (WF_ADAPTIVE: first entry of the list)
    uint wavePixels;  // pixels in the wave
    uint pad0;
    uint pad1;
};

#ifdef __cplusplus
} // namespace wf::gpu_types
static_assert(sizeof(wf::gpu_types::RenderParams) == 160);
static_assert(offsetof(wf::gpu_types::RenderParams, motionSegments) == 140);
static_assert(offsetof(wf::gpu_types::RenderParams, sceneCenter) == 96);
static_assert(offsetof(wf::gpu_types::RenderParams, clampRadiance) == 124);
static_assert(offsetof(wf::gpu_types::RenderParams, seed) == 44);
static_assert(offsetof(wf::gpu_types::RenderParams, maxDepth) == 60);
static_assert(offsetof(wf::gpu_types::RenderParams, pathCapacity) == 84);
static_assert(sizeof(wf::gpu_types::QueueCounters) ==
              64 + 8 * WF_TRACKED_DEPTHS + 20 * WF_MAX_SHADE_BINS + 32);
static_assert(offsetof(wf::gpu_types::QueueCounters, rayTrace) ==
              64 + 8 * WF_TRACKED_DEPTHS + 20 * WF_MAX_SHADE_BINS);
static_assert(offsetof(wf::gpu_types::QueueCounters, kindCount) == 64 + 8 * WF_TRACKED_DEPTHS);
static_assert(offsetof(wf::gpu_types::QueueCounters, kindArgs) ==
              64 + 8 * WF_TRACKED_DEPTHS + 4 * WF_MAX_SHADE_BINS);
static_assert(offsetof(wf::gpu_types::QueueCounters, rayArgs) == 16);
static_assert(offsetof(wf::gpu_types::QueueCounters, shadowArgs) == 32);
static_assert(offsetof(wf::gpu_types::QueueCounters, nonFiniteSamples) == 56);
static_assert(offsetof(wf::gpu_types::QueueCounters, depthRays) == 64);
static_assert(offsetof(wf::gpu_types::QueueCounters, depthShadowRays) ==
              64 + 4 * WF_TRACKED_DEPTHS);
static_assert(sizeof(wf::gpu_types::PassConstants) == 32);
static_assert(offsetof(wf::gpu_types::PassConstants, wavePixels) == 20);
#endif

#endif
