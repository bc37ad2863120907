// Per-render GPU state: parameters, queue counters, the film, and the path state as
// structure-of-arrays buffers of `pathCapacity` entries (one path per pixel sample of a wave).
// The megakernel keeps its paths in registers and gets only the parameters, counters, film and
// per-path radiance; the shadow-ray buffers exist only for scenes with emitters to connect to.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_program.h"
#include "render/shader_variant.h"

namespace wf {

class Context;

enum class PathStateUse { Megakernel, Wavefront, WavefrontWithShadowRays };

struct PathBuffers {
    // `variant` says which per-pixel extras exist (aov, secondMoment, adaptive).
    // `maxDepth`: BDPT keeps maxDepth - 2 light vertices per path, VCM maxDepth - 1.
    PathBuffers(const Context& context, uint32_t pathCapacity, uint32_t pixelCount,
                PathStateUse use, const ShaderVariant& variant, uint32_t maxDepth);
    // BDPT's (and VCM's) light vertices per path (0 for the other integrators). The shadow
    // queue holds per path a camera vertex's NEE and a connection to each it can connect to.
    static uint32_t bdptLightVertices(const ShaderVariant& variant, uint32_t maxDepth);
    // VCM's hash grid: cells for that many light vertices (RenderParams::mergeCells).
    static uint32_t mergeCells(uint32_t pathCapacity, uint32_t lightVertices);
    // What light subpaths add to the path state (their own buffers, and the shadow queue's
    // entries beyond one per path), in bytes: --verbose and the JSON's lightSubpathMemory.
    uint64_t lightSubpathBytes(uint32_t pathCapacity) const;

    void appendBindings(DescriptorBindings& bindings) const;
    void appendMemoryReport(std::vector<std::pair<std::string, uint64_t>>& report) const;

    Buffer params;
    Buffer counters;
    Buffer film;
    Buffer rayOrigin;
    Buffer rayDirection;
    Buffer throughput;
    Buffer radiance;
    Buffer hits;
    Buffer shadowOrigin;
    Buffer shadowDirection;
    Buffer shadowRadiance;
    Buffer rayQueues;
    Buffer aovPaths; // --aov only: the first hit per path, and per pixel its sums
    Buffer aovFilm;
    Buffer momentFilm;   // WF_SECOND_MOMENT: per pixel, the sum of radiance squared
    Buffer activePixels; // WF_ADAPTIVE: the pixel list waves cover
    // WF_ERROR_REPLICATES K: per pixel, K - 1 vec4s (the sums and counts of replicates 1 ..
    // K - 1; replicate 0's are the film's less theirs).
    Buffer replicateFilm;
    uint32_t replicates = 1;
    Buffer rayCones;     // WF_RAY_CONES: per path, the ray's cone width and spread (vec2)
    Buffer rayTime;      // WF_MOTION: per path, its time within the shutter (float)
    // WF_HAS_DISPERSION: per path, its wavelength (nm, 0: RGB; float); with WF_SPECTRAL_HERO
    // its four lanes (vec4 each: share of the throughput, wavelength)
    Buffer pathWavelength;
    Buffer kindQueues;   // WF_SHADE_BINS: per shade bin, pathCapacity slots of the ray queue
    // Light tracing: per path slot (a pixel in a sample slot of a whole-image wave), the light
    // subpaths' splats in 64-bit fixed point, 24 bytes (bidir/light_film.glsl); zeroed here
    // and by accumulate as it reads them.
    Buffer lightFilm;
    // BDPT (bidir/bdpt_state.glsl): per path its MIS quantities and light bounces reached; per
    // light vertex its hit, direction and throughput (bdptLightVertices per path).
    Buffer pathMis;
    Buffer lightDepths;
    Buffer lightVertexHits;
    Buffer lightVertexDirections;
    Buffer lightVertexThroughputs;
    // VCM (bidir/vcm_grid.glsl): per light vertex its position and dVM; the hash grid's lists
    // (mergeCells heads, cleared per wave, then one next link per light vertex).
    Buffer lightVertexPositions;
    Buffer mergeLists;
};

} // namespace wf
