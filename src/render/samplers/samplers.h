// The sample patterns behind sample1D/sample2D (shaders/sampling/rng.h and sampler_*.h), as the
// host names and configures them: `--sampler NAME`, `--no-randomize`, finite sets.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "shaders/sampling/sampler_common.h"

namespace wf {

enum class SamplerKind : uint32_t {
    Independent = WF_SAMPLER_INDEPENDENT,
    Stratified = WF_SAMPLER_STRATIFIED,
    Multijitter = WF_SAMPLER_MULTIJITTER,
    Halton = WF_SAMPLER_HALTON,
    Hammersley = WF_SAMPLER_HAMMERSLEY,
    Sobol = WF_SAMPLER_SOBOL,
    BlueNoise = WF_SAMPLER_BLUENOISE,
};

// The default: the lowest error at equal time on the Cornell box (README, "Samplers").
constexpr SamplerKind kDefaultSampler = SamplerKind::Sobol;

// Every sampler, in the order of --help and of converge's default method list.
const std::vector<SamplerKind>& allSamplers();
const char* samplerName(SamplerKind kind);
std::vector<std::string> samplerNames();
// UsageError naming the flag and the choices if `name` is not a sampler.
SamplerKind parseSampler(const std::string& name, const std::string& flag = "--sampler");

// Finite sets (stratified, multijitter, hammersley) need the set size up front: a render is one
// set of sppOffset + spp samples unless told otherwise (RenderSettings::sampleSetSize).
bool samplerIsFiniteSet(SamplerKind kind);
// Samplers that read the sampler table buffer (set size, primes, blue-noise mask).
bool samplerReadsTable(SamplerKind kind);

} // namespace wf
