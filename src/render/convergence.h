// The measurement behind `wavefront converge`: for one method (sampler x estimator x switches)
// and several seeds, render progressively and record at log-spaced checkpoints the sample
// count, GPU time (timestamp queries), wall time and the error against a reference.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "image/error_estimate.h"
#include "image/error_metrics.h"
#include "render/wavefront_renderer.h"

namespace wf {

class Context;
class ShaderCompiler;
struct PreparedScene;

struct ConvergenceMethod {
    std::string name; // canonical words joined by '+': "sobol+mis", "halton+mis+no-randomize"
    SamplerKind sampler = kDefaultSampler;
    LightSampling lightSampling = LightSampling::Mis;
    bool randomize = true;
    bool triangleSolidAngle = true;
    bool sphereSolidAngle = true;
    LightSelection lightSelection = LightSelection::Auto; // uniform|power|tree, else render's
    // `adaptive`: each checkpoint is a render afresh whose mean sample count is the
    // checkpoint's, placed by a pilot (render/adaptive_sampling.h), the pilot's time included.
    bool adaptive = false;
    // `guided`: path guiding (render/guiding/); each checkpoint is a render afresh with that
    // budget, its training iterations and host rebuilds in its time.
    bool guided = false;
    // `replicates`: two error replicates (--error-replicates 2), so that the recorded estimate
    // is calibrated for a correlated sampler; `adaptive` takes them anyway, as --target-error.
    bool replicates = false;
    // `light`: light tracing (--integrator light) in place of the path tracer's estimator.
    Integrator integrator = Integrator::Path;

    void applyTo(RenderSettings& settings) const;
};

// A method from words joined by '+', in any order: a sampler name, bsdf|nee|mis or the
// integrator light, a light selection uniform|power|tree, and the switches no-randomize,
// triangle-area, sphere-area, adaptive, guided, replicates. Unnamed parts take render's defaults.
// UsageError on an unknown or repeated word.
ConvergenceMethod parseMethod(const std::string& text);
// Comma-separated methods; UsageError if empty or if two name the same method.
std::vector<ConvergenceMethod> parseMethods(const std::string& list);
// Every sampler with MIS, then the default sampler with BSDF sampling and with NEE alone.
std::vector<ConvergenceMethod> defaultMethods();
std::string methodWords(); // the accepted words, for --help and errors

struct Checkpoint {
    uint32_t spp = 0;
    double gpuSeconds = 0.0;  // sum of the passes' timestamp intervals
    double wallSeconds = 0.0; // submit to fence, summed over waves
    ImageError error;       // measured against the reference
    ErrorEstimate estimate; // the render's own estimate of error.relMse, from its film
};

struct ConvergenceOptions {
    std::vector<uint32_t> seeds;
    double timeBudget = 4.0; // seconds of wall time per seed: the first seed doubles the
                             // sample count until a checkpoint reaches it
    uint32_t maxSpp = 1u << 16;
    // Fixed checkpoints (spp, increasing) instead of the time budget: for tests.
    std::vector<uint32_t> fixedCheckpoints;
    bool keepFirstSeedImages = true;
};

struct MethodRun {
    ConvergenceMethod method;
    std::vector<uint32_t> checkpoints;             // spp, the same for every seed
    std::vector<std::vector<Checkpoint>> perSeed;  // [seed][checkpoint]
    std::vector<std::vector<float>> firstSeedImages; // [checkpoint], when kept
    ShaderDefines defines;
};

// Renders `method` for every seed. Progressive samplers render each seed once, adding samples
// up to each checkpoint; finite-set samplers (stratified, multijitter, hammersley) render each
// checkpoint afresh as a set of that size, since a prefix of a set is not a good pattern.
// `base` supplies size, depth and the like; `onCheckpoint` (optional) reports progress.
MethodRun runConvergence(const Context& context, const PreparedScene& scene,
                         const ShaderCompiler& compiler, const RenderSettings& base,
                         const ConvergenceMethod& method, const ConvergenceOptions& options,
                         const std::vector<float>& reference,
                         const std::function<void(uint32_t seed, const Checkpoint&)>&
                             onCheckpoint = {});

} // namespace wf
