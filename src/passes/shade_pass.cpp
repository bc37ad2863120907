#include "passes/shade_pass.h"

#include <cstddef>
#include <string>

namespace wf {
namespace {

// The scene's defines with those of one kind's pass: its bin, and its kind's BSDF alone.
ShaderDefines kindDefines(const ShaderDefines& scene, uint32_t bin, ShadeKind kind) {
    ShaderDefines defines = scene;
    auto set = [&](const std::string& name, const std::string& value) {
        for (auto& [key, old] : defines)
            if (key == name) {
                old = value;
                return;
            }
        defines.push_back({name, value});
    };
    set("WF_SHADE_BIN", std::to_string(bin));
    if (kind == ShadeKind::General)
        return defines; // the scene's BSDF, for every kind
    set("WF_BSDF_DIFFUSE_ONLY", kind == ShadeKind::Diffuse ? "1" : "0");
    set("WF_BSDF_DELTA_ONLY", kind == ShadeKind::Specular ? "1" : "0");
    set("WF_BSDF_NO_LAYERS", "1");
    return defines;
}

const char* kindPassName(ShadeKind kind) {
    switch (kind) {
    case ShadeKind::Diffuse: return "shade diffuse";
    case ShadeKind::Specular: return "shade specular";
    default: return "shade general";
    }
}

PassResources withDefines(const PassResources& resources, const ShaderDefines& defines) {
    return {resources.context, resources.compiler, defines,
            resources.table,   resources.counters, resources.timer};
}

} // namespace

ShadePass::ShadePass(const PassResources& resources, uint32_t bin, ShadeKind kind)
    : pass_(withDefines(resources, kindDefines(resources.defines, bin, kind)),
            kindPassName(kind), "shade.comp"),
      argsOffset_(offsetof(gpu_types::QueueCounters, kindArgs) +
                  bin * sizeof(gpu_types::DispatchArgs)) {}

void ShadePass::record(VkCommandBuffer cmd, uint32_t depth, const PassConstants& wave) const {
    PassConstants constants = wave;
    constants.depth = depth;
    pass_.dispatchIndirect(cmd, argsOffset_, constants);
}

} // namespace wf
