// What a render is asked to do: image size, samples, estimator and sampler choices, and the
// switches that pick shader variants or buffer layouts (each says whether it changes the image).
#pragma once
#include <cstdint>

#include "render/samplers/samplers.h"
#include "passes/shade_kinds.h"
#include "render/shader_variant.h"

namespace wf {

enum class Traversal { Bvh, RayTracing };

struct RenderSettings {
    uint32_t width = 512;
    uint32_t height = 512;
    uint32_t samplesPerPixel = 64;
    // --time-limit: render() stops before a sample pass that its pace so far says would end
    // past this many seconds of wall time (0: none). The first pass always runs.
    double timeLimitSeconds = 0.0;
    uint32_t maxDepth = 16;
    uint32_t rrDepth = 3;
    uint32_t seed = 0;
    uint32_t maxPathsPerWave = 1u << 20; // bounds buffer sizes and the length of one submit
    // Waves are sized so that one submit takes about this long or less, so that a long render
    // never trips a GPU watchdog (0: waves of maxPathsPerWave regardless of time).
    double submitBudgetSeconds = 0.25;
    // GPU time per pass in stats().passMilliseconds (bench, --json, the viewer, Python); false:
    // one "waves" entry, the waves' GPU time, for renders that read no pass times (a plain
    // render, converge), as timestamps cost lavapipe about 0.07 ms each (gpu/timestamp_timer.h).
    bool timePasses = true;
    // Trace whole paths in one dispatch (shaders/megakernel.comp) instead of the wavefront's
    // passes: the baseline `wavefront bench` compares against. Same samples, same image.
    bool megakernel = false;
    // --traversal: the project's BVH in compute, or the driver's acceleration structures
    // through ray-tracing pipelines (needs a context with ray tracing enabled; the megakernel
    // always walks the BVH). The same image up to the intersectors' rounding.
    Traversal traversal = Traversal::Bvh;
    // --integrator: light tracing renders whole samples of the image per wave (its splats
    // land anywhere), and is refused with the megakernel, --traversal rt, guiding, pixel lists
    // (--target-error), motion blur and cameras without a lens (WavefrontRenderer).
    Integrator integrator = Integrator::Path;
    // --bdpt-heuristic balance: bdpt (and vcm) weigh their strategies by the balance heuristic
    // instead of the power heuristic (the default). Another image of the same expectation.
    bool bdptBalance = false;
    // --vcm-radius: vcm's merging radius at sample index 0, as a fraction of the scene's
    // bounding-sphere radius; sample index i merges within r (i + 1)^-1/8 (bidir/vcm_grid.glsl).
    float vcmRadius = 0.01f;
    // --light-share N: light, bdpt and vcm trace one light subpath per N pixels per sample,
    // which those pixels' camera subpaths share (shaders/bidir/light_share.glsl); 0 takes the
    // integrator's default (kDefaultLightShare). Another image of the same expectation.
    uint32_t lightShare = 0;
    // --spectral: in scenes with dispersion only, one wavelength per path or four (hero
    // wavelengths with spectral MIS; shader_variant.h). Another image of the same expectation.
    SpectralSampling spectral = SpectralSampling::Single;
    LightSampling lightSampling = LightSampling::Mis;
    LightSelection lightSelection = LightSelection::Auto; // --light-selection
    bool triangleSolidAngle = true; // --triangle-sampling solid-angle (else area)
    bool sphereSolidAngle = true;   // --sphere-sampling solid-angle (else area)
    float minThroughput = 0.0f;     // --min-throughput: biased termination, 0 = off
    float clampRadiance = 0.0f;     // --clamp: biased firefly clamp, 0 = off
    SamplerKind sampler = kDefaultSampler; // --sampler
    bool randomizeSamples = true;   // --no-randomize turns it off
    // --error-replicates K: each pixel's samples split into K independently randomized copies
    // of the sampler's sequence (sample i is sample i / K of replicate i % K), so that the
    // spread of the replicates' means measures the error of any sampler, correlated or not
    // (render/film_error.h). 1: one sequence, as without. The independent sampler ignores it:
    // its samples are independent already.
    uint32_t errorReplicates = 1;
    uint32_t sppOffset = 0;         // --spp-offset: index of the first sample per pixel
    // Finite-set samplers (stratified, multijitter, hammersley): samples in one set, 0 =
    // sppOffset + samplesPerPixel (--spp-total). Parts of one render must agree on it.
    uint32_t sampleSetSize = 0;
    // Store 16-byte path-state entries as two 64-bit words where the device has shaderInt64
    // (WF_PACKED_STORES, faster on lavapipe); off, the vec4 stores every device has. Same image.
    bool packedStores = true;
    // Keep the traversal stack in vectors where the tree's stack need fits in 8 entries, and
    // any-hit traversal's where it fits in 16 (WF_BVH_REGISTER_STACK, faster on lavapipe);
    // off, a private array. Same image.
    bool registerStack = true;
    // --aov: also accumulate the camera ray's first hit (albedo, shading normal, distance) and
    // the radiance squared per pixel (readAovs). The wavefront only; the image is unchanged.
    bool aov = false;
    // Textured scenes: filter textures by ray cones from their mip chains (WF_RAY_CONES,
    // ray_cones.glsl); off, every lookup reads level 0 bilinearly, as before the chains.
    bool textureLod = true;
    // Scenes with materials of two or more kinds (shade_kinds.h): bin each bounce's hits by
    // kind and shade each bin with a pass compiled for its kind. Auto splits only scenes
    // without the general kind, where it paid; On splits any scene of two kinds or more; Off
    // keeps one pass for every hit, as single-kind scenes always have. The same image up to
    // float rounding.
    ShadeSplit shadeSplit = ShadeSplit::Auto;
    // Keep each pixel's sum of squares and largest sample (the moment film), from which every
    // render estimates its own error (error_estimate.h). The viewer, which shows none, saves
    // the writes. The image is the same either way.
    bool errorEstimate = true;
    // --target-error: waves cover lists of pixels (renderPixelList) and the film keeps each
    // pixel's radiance squared (readMoments); render() and the progressive calls are refused.
    bool pixelList = false;
    // Most bytes of the triangle or BVH table in one buffer (0: the device's limit); a test
    // sets it low to spread a small scene over pages as a large one spreads.
    uint64_t tablePageBytes = 0;
    // --guiding on: path guiding (render/guiding/path_guide.h, WF_GUIDING). render() trains the
    // guide over iterations of 1, 2, 4, ... spp while the last iteration keeps at least half
    // of samplesPerPixel, then renders the rest with the frozen guide. Sample indices
    // continue across iterations. The image: guideCombineIterations, every iteration's image
    // weighted by its samples, the mean of all (render/guiding/guide_combination.h); else the
    // last iteration's alone.
    bool guiding = false;
    bool guideCombineIterations = true;
    float guideBsdfFraction = 0.5f; // the BSDF's share of the one-sample mixture
    // Each spatial leaf learns its own share (the candidate whose records' second moment was
    // least, guide_tree.h); guideBsdfFraction until a leaf has learnt one.
    bool guideLearnFraction = true;
    // Parallax: each leaf's quadtree holds directions seen from its centre to radiance at a
    // learnt distance, reprojected to each vertex (guide_tree.h); off: directions as recorded.
    bool guideParallax = true;
    // Vertices of bounce index below this are guided, and those reached by a Dirac bounce;
    // the rest sample the BSDF alone (docs/guiding.md: guiding every vertex compounds the
    // mixture's doubled weights where the guide is blurred).
    uint32_t guideMaxDepth = 1;
    // At most this many training iterations (tests set 0 to render with a guide they froze
    // themselves through WavefrontRenderer::guide()).
    uint32_t guideMaxIterations = 0xffffffffu;
    // --guiding auto (the default): the command decides `guiding` per scene once it is loaded
    // (resolveGuiding, guiding_schedule.h's rule); unresolved, auto guides nothing.
    bool guidingAuto = false;
};

} // namespace wf
