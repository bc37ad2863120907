#include "render/samplers/samplers.h"

#include "errors.h"

namespace wf {

const std::vector<SamplerKind>& allSamplers() {
    static const std::vector<SamplerKind> kinds = {
        SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Multijitter,
        SamplerKind::Halton,      SamplerKind::Hammersley, SamplerKind::Sobol,
        SamplerKind::BlueNoise};
    return kinds;
}

const char* samplerName(SamplerKind kind) {
    switch (kind) {
    case SamplerKind::Independent: return "independent";
    case SamplerKind::Stratified: return "stratified";
    case SamplerKind::Multijitter: return "multijitter";
    case SamplerKind::Halton: return "halton";
    case SamplerKind::Hammersley: return "hammersley";
    case SamplerKind::Sobol: return "sobol";
    case SamplerKind::BlueNoise: return "bluenoise";
    }
    return "?";
}

std::vector<std::string> samplerNames() {
    std::vector<std::string> names;
    for (SamplerKind kind : allSamplers())
        names.push_back(samplerName(kind));
    return names;
}

SamplerKind parseSampler(const std::string& name, const std::string& flag) {
    std::string list;
    for (SamplerKind kind : allSamplers()) {
        if (name == samplerName(kind))
            return kind;
        list += (list.empty() ? "" : ", ") + std::string(samplerName(kind));
    }
    throw UsageError(flag + " expects one of " + list + ", got '" + name + "'");
}

bool samplerIsFiniteSet(SamplerKind kind) {
    return kind == SamplerKind::Stratified || kind == SamplerKind::Multijitter ||
           kind == SamplerKind::Hammersley;
}

bool samplerReadsTable(SamplerKind kind) {
    return kind != SamplerKind::Independent && kind != SamplerKind::Sobol;
}

} // namespace wf
