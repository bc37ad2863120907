#include "render/shader_variant.h"

#include <algorithm>
#include <bit>
#include <cstdio>

#include "errors.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/integrator_support.h"
#include "passes/shade_kinds.h"
#include "render/wavefront_renderer.h"
#include "passes/workgroup.h"

namespace wf {

ShaderVariant chooseVariant(const PreparedScene& scene, const RenderSettings& settings) {
    const LightTable& lights = scene.lights;
    ShaderVariant variant;
    // Without a light there is no light subpath: BDPT (and VCM) is then the path tracer.
    variant.integrator = bidirectional(settings.integrator) && lights.emitters.empty()
                             ? Integrator::Path
                             : settings.integrator;
    variant.bdptBalance = bidirectional(variant.integrator) && settings.bdptBalance;
    // BDPT's strategies include next-event estimation, weighed by its own MIS.
    variant.lightSampling = bidirectional(settings.integrator) ? LightSampling::Mis
                                                               : settings.lightSampling;
    // Light tracing reads the emitter table for its emission, whatever --light-sampling says
    // (its camera rays only add the emission they find).
    variant.nextEventEstimation =
        (settings.lightSampling != LightSampling::Bsdf ||
         settings.integrator != Integrator::Path) &&
        !lights.emitters.empty();
    variant.triangleEmitters = variant.nextEventEstimation && lights.triangleEmitters > 0;
    variant.sphereLights = lights.sphereLights > 0;
    variant.deltaLights = variant.nextEventEstimation && lights.deltaLights > 0;
    variant.environment = lights.environmentEmitter != WF_NO_EMITTER;
    variant.lightSelection = settings.lightSelection;
    if (variant.lightSelection == LightSelection::Auto)
        variant.lightSelection = scene.lightTree.lights >= kLightTreeMinLights
                                     ? LightSelection::Tree
                                     : LightSelection::Power;
    if (variant.lightSelection == LightSelection::Tree && scene.lightTree.nodes.empty())
        variant.lightSelection = LightSelection::Power; // only lights beside a tree
    // Light subpaths start from a light chosen by the table's pmf alone (the tree's choice
    // needs a receiving point), so light tracing takes power where NEE would take the tree.
    if (variant.integrator != Integrator::Path && variant.lightSelection == LightSelection::Tree)
        variant.lightSelection = LightSelection::Power;
    variant.triangleSolidAngle = settings.triangleSolidAngle;
    variant.sphereSolidAngle = settings.sphereSolidAngle;
    // Texture factors multiply these, so zero factors stay zero whatever the textures hold.
    variant.diffuseOnly = std::all_of(
        scene.materials.begin(), scene.materials.end(), [](const Material& m) {
            return m.metallic <= 0.0f && m.specular <= 0.0f && m.transmission <= 0.0f &&
                   m.diffuseTransmission <= 0.0f;
        });
    // One shade pass per kind only where the scene holds two kinds or more: a scene of one kind
    // keeps its single shade pass and shaders. Set for the megakernel too, which ignores it, so
    // that bench's two renderers share one set of scene buffers (the bins ride in them).
    // Light tracing shades its camera rays at depth 0 only and its light vertices in one pass.
    variant.shadeKinds = settings.integrator != Integrator::Path
                             ? 0u
                             : shadeKindsFor(shadeKindsPresent(scene.materials),
                                             settings.shadeSplit);
    // Material extensions compile in only where some material uses them (zero factors stay
    // zero whatever their textures hold; absorption acts only inside transmissive meshes,
    // diffuse transmission's included).
    for (const Material& m : scene.materials) {
        const bool coat = m.clearcoat > 0.0f;
        const bool sheen = std::max({m.sheenColor.x, m.sheenColor.y, m.sheenColor.z}) > 0.0f;
        const bool transmits = m.transmission > 0.0f || m.diffuseTransmission > 0.0f;
        const bool volume = transmits && m.thickness > 0.0f &&
                            std::max({m.attenuation.x, m.attenuation.y, m.attenuation.z}) > 0.0f;
        variant.clearcoat |= coat;
        variant.sheen |= sheen;
        variant.iridescence |= m.iridescence > 0.0f;
        variant.anisotropy |= m.anisotropyStrength > 0.0f;
        variant.diffuseTransmission |= m.diffuseTransmission > 0.0f;
        variant.dispersion |= gpu_types::materialDisperses(m);
        variant.volume |= volume;
        variant.specularTextures |=
            m.specularTexture != WF_NO_TEXTURE || m.specularColorTexture != WF_NO_TEXTURE;
        variant.clearcoatTextures |= coat && (m.clearcoatTexture != WF_NO_TEXTURE ||
                                              m.clearcoatRoughnessTexture != WF_NO_TEXTURE);
        variant.clearcoatNormalMaps |= coat && m.clearcoatNormalTexture != WF_NO_TEXTURE;
        variant.sheenTextures |= sheen && (m.sheenColorTexture != WF_NO_TEXTURE ||
                                           m.sheenRoughnessTexture != WF_NO_TEXTURE);
        variant.thicknessTextures |= volume && m.thicknessTexture != WF_NO_TEXTURE;
    }
    variant.heroWavelengths = variant.dispersion && settings.spectral == SpectralSampling::Hero;
    // The smallest register stack that holds the tree's stack need (bvh_traverse.h).
    const uint32_t need = scene.bvhStats.stackNeed;
    variant.registerStack = !settings.registerStack               ? 0u
                            : need <= 8u                          ? 8u
                            : need <= WF_BVH_REGISTER_STACK_SIZE ? WF_BVH_REGISTER_STACK_SIZE
                                                                  : 0u;
    variant.aov = settings.aov && !settings.megakernel;
    variant.secondMoment = settings.aov || settings.pixelList || settings.errorEstimate;
    variant.adaptive = settings.pixelList;
    variant.thinLens = scene.camera.aperture > 0.0f;
    variant.instances = !scene.instances.empty();
    variant.motion = scene.motionSegments > 0;
    variant.lightShare =
        lightShareFor(settings, variant.integrator, variant.motion, scene.materials);
    variant.sampler = settings.sampler;
    variant.randomizeSamples = settings.randomizeSamples;
    variant.errorReplicates = errorReplicatesFor(settings);
    return variant;
}

uint32_t errorReplicatesFor(const RenderSettings& settings) {
    // A guided render's image combines its training iterations (guide_combination.h), which
    // replicates would have to follow one by one: it keeps the bound. Guided --target-error
    // rounds sample a frozen guide and take them.
    if (settings.sampler == SamplerKind::Independent || (settings.guiding && !settings.pixelList))
        return 1;
    return std::max(settings.errorReplicates, 1u);
}

uint32_t ShaderVariant::shadeBins() const {
    return static_cast<uint32_t>(std::popcount(shadeKinds));
}

ShaderDefines ShaderVariant::defines() const {
    auto flag = [](bool on) { return std::string(on ? "1" : "0"); };
    ShaderDefines defines = {{"WF_WORKGROUP_SIZE", std::to_string(kWorkgroupSize)},
            {"WF_LIGHT_SAMPLING", std::to_string(static_cast<int>(lightSampling))},
            {"WF_HAS_EMITTERS", flag(nextEventEstimation)},
            {"WF_HAS_TRIANGLE_EMITTERS", flag(triangleEmitters)},
            {"WF_HAS_SPHERE_LIGHTS", flag(sphereLights)},
            {"WF_HAS_DELTA_LIGHTS", flag(deltaLights)},
            {"WF_HAS_LIGHTS", flag(lightsBuffer())},
            {"WF_HAS_ENVIRONMENT", flag(environment)},
            {"WF_LIGHT_TREE", flag(lightTree())},
            {"WF_TRIANGLE_SOLID_ANGLE", flag(triangleSolidAngle)},
            {"WF_SPHERE_SOLID_ANGLE", flag(sphereSolidAngle)},
            {"WF_BSDF_DIFFUSE_ONLY", flag(diffuseOnly)},
            {"WF_HAS_CLEARCOAT", flag(clearcoat)},
            {"WF_HAS_SHEEN", flag(sheen)},
            {"WF_HAS_IRIDESCENCE", flag(iridescence)},
            {"WF_HAS_VOLUME", flag(volume)},
            {"WF_HAS_SPECULAR_TEXTURES", flag(specularTextures && surface.textures)},
            {"WF_HAS_CLEARCOAT_TEXTURES", flag(clearcoatTextures && surface.textures)},
            {"WF_HAS_CLEARCOAT_NORMAL_MAPS", flag(clearcoatNormalMaps && surface.normalMaps)},
            {"WF_HAS_SHEEN_TEXTURES", flag(sheenTextures && surface.textures)},
            {"WF_HAS_THICKNESS_TEXTURES", flag(thicknessTextures && surface.textures)},
            {"WF_HAS_TEXTURES", flag(surface.textures)},
            {"WF_TEXEL_PAGES", std::to_string(surface.texelPages)},
            {"WF_HAS_TEXCOORD1", flag(surface.texcoord1)},
            {"WF_HAS_NORMALS", flag(surface.normals)},
            {"WF_HAS_VERTEX_COLORS", flag(surface.vertexColors)},
            {"WF_HAS_NORMAL_MAPS", flag(surface.normalMaps)},
            {"WF_HAS_ALPHA_MASK", flag(surface.alphaMask)},
            {"WF_RAY_CONES", flag(rayCones)},
            {"WF_GUIDING", flag(guiding)},
            {"WF_SAMPLER", std::to_string(static_cast<uint32_t>(sampler))},
            {"WF_SAMPLER_RANDOMIZE", flag(randomizeSamples)},
            {"WF_PACKED_STORES", flag(packedStores)},
            {"WF_BVH_REGISTER_STACK", std::to_string(registerStack)},
            {"WF_AOV", flag(aov)},
            {"WF_SECOND_MOMENT", flag(secondMoment)},
            {"WF_ADAPTIVE", flag(adaptive)},
            {"WF_THIN_LENS", flag(thinLens)},
            {"WF_HAS_INSTANCES", flag(instances)},
            {"WF_TRIANGLE_PAGES", std::to_string(trianglePages.count)},
            {"WF_TRIANGLE_PAGE_SHIFT", std::to_string(trianglePages.shift)},
            {"WF_BVH_PAGES", std::to_string(bvhPages.count)},
            {"WF_BVH_PAGE_SHIFT", std::to_string(bvhPages.shift)},
            {"WF_INSTANCE_PAGES", std::to_string(instancePages.count)},
            {"WF_INSTANCE_PAGE_SHIFT", std::to_string(instancePages.shift)}};
    if (rayTracing)
        defines.emplace_back("WF_RAY_TRACING", "1");
    if (errorReplicates > 1) // defined only then, so one sequence's shaders are as before
        defines.emplace_back("WF_ERROR_REPLICATES", std::to_string(errorReplicates));
    if (motion) // defined only then, so still scenes' shaders are as before
        defines.emplace_back("WF_MOTION", "1");
    if (integrator != Integrator::Path)
        defines.emplace_back("WF_INTEGRATOR",
                             std::to_string(static_cast<int>(
                                 bidirectional(integrator) ? Integrator::Bdpt : integrator)));
    if (integrator == Integrator::Vcm)
        defines.emplace_back("WF_VCM", "1");
    if (bidirectional(integrator) && bdptBalance)
        defines.emplace_back("WF_BDPT_MIS_EXPONENT", "1.0");
    if (anisotropy) { // defined only then, so isotropic scenes' shaders are as before
        defines.emplace_back("WF_HAS_ANISOTROPY", "1");
        defines.emplace_back("WF_HAS_TANGENTS", flag(surface.tangents));
    }
    if (diffuseTransmission) // defined only then, as anisotropy
        defines.emplace_back("WF_HAS_DIFFUSE_TRANSMISSION", "1");
    if (dispersion) // defined only then: other scenes keep their shaders and sample numbering
        defines.emplace_back("WF_HAS_DISPERSION", "1");
    if (dispersion && heroWavelengths)
        defines.emplace_back("WF_SPECTRAL_HERO", "1");
    if (shadeKinds != 0) {
        defines.push_back({"WF_SHADE_BINS", std::to_string(shadeBins())});
        defines.push_back({"WF_LIGHT_HIT_BIN", std::to_string(lightHitBin(shadeKinds))});
    }
    return defines;
}

std::string ShaderVariant::describe() const {
    std::string text;
    for (const auto& [name, value] : defines())
        text += (text.empty() ? "" : " ") + name + "=" + value;
    return text;
}

LightSampling parseLightSampling(const std::string& name) {
    if (name == "bsdf")
        return LightSampling::Bsdf;
    if (name == "nee")
        return LightSampling::Nee;
    if (name == "mis")
        return LightSampling::Mis;
    throw UsageError("--light-sampling expects bsdf, nee or mis, got '" + name + "'");
}

const char* lightSamplingName(LightSampling mode) {
    switch (mode) {
    case LightSampling::Bsdf: return "bsdf";
    case LightSampling::Nee: return "nee";
    default: return "mis";
    }
}

std::string describeLightSelection(const PreparedScene& scene, const ShaderVariant& variant) {
    if (!variant.nextEventEstimation)
        return "none (no light sampling)";
    std::string text = lightSelectionName(variant.lightSelection);
    if (variant.lightTree()) {
        const LightTree& tree = scene.lightTree;
        char detail[160];
        std::snprintf(detail, sizeof detail,
                      " (light tree of %u lights, %zu nodes, depth %u, built in %.1f ms)",
                      tree.lights, tree.nodes.size(), tree.depth, tree.buildSeconds * 1e3);
        text += detail;
    }
    return text;
}

SpectralSampling parseSpectralSampling(const std::string& name) {
    if (name == "single")
        return SpectralSampling::Single;
    if (name == "hero")
        return SpectralSampling::Hero;
    throw UsageError("--spectral expects single or hero, got '" + name + "'");
}

const char* spectralSamplingName(SpectralSampling mode) {
    return mode == SpectralSampling::Hero ? "hero" : "single";
}

Integrator parseIntegrator(const std::string& name) {
    if (name == "path")
        return Integrator::Path;
    if (name == "light")
        return Integrator::Light;
    if (name == "bdpt")
        return Integrator::Bdpt;
    if (name == "vcm")
        return Integrator::Vcm;
    throw UsageError("--integrator expects path, light, bdpt or vcm, got '" + name + "'");
}

const char* integratorName(Integrator integrator) {
    switch (integrator) {
    case Integrator::Light: return "light";
    case Integrator::Bdpt: return "bdpt";
    case Integrator::Vcm: return "vcm";
    default: return "path";
    }
}

LightSelection parseLightSelection(const std::string& name) {
    if (name == "uniform")
        return LightSelection::Uniform;
    if (name == "power")
        return LightSelection::Power;
    if (name == "tree")
        return LightSelection::Tree;
    throw UsageError("--light-selection expects uniform, power or tree, got '" + name + "'");
}

const char* lightSelectionName(LightSelection selection) {
    switch (selection) {
    case LightSelection::Uniform: return "uniform";
    case LightSelection::Power: return "power";
    case LightSelection::Tree: return "tree";
    default: return "auto";
    }
}

} // namespace wf
