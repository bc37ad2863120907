// The structs in shaders/types/*.h are compiled by both C++ and glslang. This test asks
// glslang's reflection for the std430 offset of every member the shaders see and compares it
// with the C++ offsetof, so a layout drift fails here instead of corrupting a render.
#include <cstddef>
#include <initializer_list>
#include <map>
#include <string>
#include <utility>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <gtest/gtest.h>

#include "shaders/types/render_types.h"
#include "shaders/types/texture_types.h"
#include "shaders/sampling/sampler_tables.h"
#include "shaders/types/light_types.h"
#include "shaders/types/scene_types.h"
#include "shaders/types/texture_types.h"

namespace wf {
namespace {

using namespace gpu_types;

std::map<std::string, int> reflectedOffsets() {
    const char* source = R"(#version 460
#include "types/scene_types.h"
#include "types/render_types.h"
#include "types/light_types.h"
#include "types/texture_types.h"
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer B0 {
    Triangle tri; BvhNode node; Material mat; Emitter em; BvhPair pair; };
layout(std140, binding = 4) uniform U0 { RenderParams params; }; // a uniform buffer: std140
layout(std430, binding = 1) buffer B1 { QueueCounters counters; uint paramsSum; };
layout(std430, binding = 2) buffer B2 { PunctualLight light; };
layout(std430, binding = 3) buffer B3 {
    TextureRef tref; TriangleNormals tnorm; TriangleTangents ttan; TriangleUvs tuv[2]; };
void main() {
    tri.pad = tri.material + tri.emitter + uint(tri.p0.x + tri.p1.x + tri.p2.x);
    node.count = node.rightOrFirst + uint(node.lo.x + node.hi.x);
    mat.flags = uint(mat.baseColor.x + mat.emission.x + mat.metallic + mat.roughness + mat.ior +
        mat.transmission + mat.specularColor.x + mat.specular + mat.alphaCutoff +
        mat.normalScale) + mat.baseColorTexture + mat.metallicRoughnessTexture +
        mat.normalTexture + mat.emissiveTexture + mat.transmissionTexture + mat.pad +
        mat.specularTexture + mat.specularColorTexture + uint(mat.clearcoat +
        mat.clearcoatRoughness + mat.sheenColor.x + mat.sheenRoughness + mat.attenuation.x +
        mat.thickness + mat.clearcoatNormalScale) + mat.clearcoatTexture +
        mat.clearcoatRoughnessTexture + mat.clearcoatNormalTexture + mat.sheenColorTexture +
        mat.sheenRoughnessTexture + mat.thicknessTexture + mat.pad3;
    em.alias = em.source + uint(em.pmf + em.aliasProb);
    pair.pad1 = pair.child0 + pair.child1 + pair.pad0 + uint(pair.lo0.x + pair.hi0.x + pair.lo1.x +
        pair.hi1.x);
    paramsSum = params.environmentHeight + uint(params.cameraPosition.x + params.tanHalfFovY +
        params.cameraForward.x + params.aspect + params.cameraUp.x + params.cameraRight.x +
        params.sceneCenter.x + params.sceneRadius + params.minThroughput +
        params.clampRadiance) + params.seed + params.maxDepth + params.width + params.height +
        params.pixelCount + params.rrDepth + params.emitterCount + params.pathCapacity +
        params.sphereLightCount + params.environmentEmitter + params.environmentWidth;
    counters.pad2 = counters.rayCount + counters.shadowCount + counters.rayArgs.count +
        counters.rayArgs.groupsX + counters.shadowArgs.groupsX + counters.shadowArgs.count +
        counters.extensionRays + counters.shadowRays + counters.nonFiniteSamples +
        counters.depthRays[3] + counters.depthShadowRays[2] + counters.kindCount[1] +
        counters.kindArgs[2].count;
    light.emitter = light.type + uint(light.position.x + light.direction.x + light.radius +
        light.intensity.x + light.cosInner + light.cosOuter + float(light.motion) + light.pad2);
    tref.levels = tref.page + tref.offset + tref.width + tref.height + tref.flags +
        uint(tref.uRow.x + tref.vRow.x) + tnorm.n0 + tnorm.n1 + tnorm.n2 + tnorm.pad +
        ttan.t0 + ttan.t1 + ttan.t2 + ttan.signs + uint(tuv[1].uv0.x + tuv[1].uv1.x + tuv[1].uv2.x);
}
)";
    glslang::InitializeProcess();
    std::map<std::string, int> offsets;
    {
        glslang::TShader shader(EShLangCompute);
        shader.setStrings(&source, 1);
        std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
        shader.setPreamble(preamble.c_str());
        shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
        shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
        shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
        struct Includer : glslang::TShader::Includer {
            IncludeResult* includeLocal(const char* name, const char*, size_t) override {
                std::string path = std::string(WF_SOURCE_SHADER_DIR) + "/" + name;
                FILE* file = std::fopen(path.c_str(), "rb");
                if (!file)
                    return nullptr;
                auto* text = new std::string;
                char buffer[4096];
                size_t n;
                while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0)
                    text->append(buffer, n);
                std::fclose(file);
                return new IncludeResult(path, text->data(), text->size(), text);
            }
            void releaseInclude(IncludeResult* result) override {
                if (result) {
                    delete static_cast<std::string*>(result->userData);
                    delete result;
                }
            }
        } includer;
        auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
        EXPECT_TRUE(shader.parse(GetDefaultResources(), 460, false, messages, includer))
            << shader.getInfoLog();
        glslang::TProgram program;
        program.addShader(&shader);
        EXPECT_TRUE(program.link(messages)) << program.getInfoLog();
        EXPECT_TRUE(program.buildReflection(EShReflectionAllBlockVariables));
        // glslang 12 lists the members of storage blocks among its "uniform" variables.
        for (int i = 0; i < program.getNumUniformVariables(); ++i) {
            const auto& variable = program.getUniform(i);
            offsets[variable.name] = variable.offset;
        }
    }
    glslang::FinalizeProcess();
    return offsets;
}

TEST(SharedLayout, GlslOffsetsMatchCpp) {
    auto offsets = reflectedOffsets();
    ASSERT_FALSE(offsets.empty());
    auto expectOffset = [&](const std::string& name, size_t base, size_t offset) {
        auto it = offsets.find(name);
        ASSERT_NE(it, offsets.end()) << name << " not reflected";
        EXPECT_EQ(size_t(it->second), base + offset) << name;
    };
    expectOffset("tri.p1", 0, offsetof(Triangle, p1));
    expectOffset("tri.emitter", 0, offsetof(Triangle, emitter));
    expectOffset("tri.p2", 0, offsetof(Triangle, p2));
    expectOffset("tri.pad", 0, offsetof(Triangle, pad));
    expectOffset("node.hi", sizeof(Triangle), offsetof(BvhNode, hi));
    expectOffset("node.count", sizeof(Triangle), offsetof(BvhNode, count));
    const size_t materialBase = sizeof(Triangle) + sizeof(BvhNode);
    expectOffset("mat.emission", materialBase, offsetof(Material, emission));
    expectOffset("mat.flags", materialBase, offsetof(Material, flags));
    expectOffset("mat.specularColor", materialBase, offsetof(Material, specularColor));
    expectOffset("mat.specular", materialBase, offsetof(Material, specular));
    expectOffset("mat.normalScale", materialBase, offsetof(Material, normalScale));
    expectOffset("mat.pad", materialBase, offsetof(Material, pad));
    expectOffset("mat.specularTexture", materialBase, offsetof(Material, specularTexture));
    expectOffset("mat.specularColorTexture", materialBase,
                 offsetof(Material, specularColorTexture));
    expectOffset("mat.clearcoat", materialBase, offsetof(Material, clearcoat));
    expectOffset("mat.clearcoatRoughness", materialBase, offsetof(Material, clearcoatRoughness));
    expectOffset("mat.sheenColor", materialBase, offsetof(Material, sheenColor));
    expectOffset("mat.sheenRoughness", materialBase, offsetof(Material, sheenRoughness));
    expectOffset("mat.attenuation", materialBase, offsetof(Material, attenuation));
    expectOffset("mat.thickness", materialBase, offsetof(Material, thickness));
    // The layers' textures (issue 48), a block of their own at the end.
    for (const auto& [name, offset] : std::initializer_list<std::pair<const char*, size_t>>{
             {"mat.clearcoatTexture", offsetof(Material, clearcoatTexture)},
             {"mat.clearcoatRoughnessTexture", offsetof(Material, clearcoatRoughnessTexture)},
             {"mat.clearcoatNormalTexture", offsetof(Material, clearcoatNormalTexture)},
             {"mat.clearcoatNormalScale", offsetof(Material, clearcoatNormalScale)},
             {"mat.sheenColorTexture", offsetof(Material, sheenColorTexture)},
             {"mat.sheenRoughnessTexture", offsetof(Material, sheenRoughnessTexture)},
             {"mat.thicknessTexture", offsetof(Material, thicknessTexture)},
             {"mat.pad3", offsetof(Material, pad3)}})
        expectOffset(name, materialBase, offset);
    // Anisotropy (texel 13), after them.
    expectOffset("mat.anisotropyStrength", materialBase, offsetof(Material, anisotropyStrength));
    expectOffset("mat.anisotropyTexture", materialBase, offsetof(Material, anisotropyTexture));
    expectOffset("mat.anisotropyRotation", materialBase, offsetof(Material, anisotropyRotation));
    // Diffuse transmission (texels 14-15), last.
    expectOffset("mat.diffuseTransmissionColor", materialBase,
                 offsetof(Material, diffuseTransmissionColor));
    expectOffset("mat.diffuseTransmission", materialBase, offsetof(Material, diffuseTransmission));
    expectOffset("mat.diffuseTransmissionTexture", materialBase,
                 offsetof(Material, diffuseTransmissionTexture));
    expectOffset("mat.diffuseTransmissionColorTexture", materialBase,
                 offsetof(Material, diffuseTransmissionColorTexture));
    expectOffset("mat.dispersion", materialBase, offsetof(Material, dispersion));
    expectOffset("mat.pad5", materialBase, offsetof(Material, pad5));
    expectOffset("em.alias", materialBase + sizeof(Material), offsetof(Emitter, alias));
    const size_t pairBase = materialBase + sizeof(Material) + sizeof(Emitter);
    expectOffset("pair.child0", pairBase, offsetof(BvhPair, child0));
    expectOffset("pair.hi0", pairBase, offsetof(BvhPair, hi0));
    expectOffset("pair.lo1", pairBase, offsetof(BvhPair, lo1));
    expectOffset("pair.child1", pairBase, offsetof(BvhPair, child1));
    expectOffset("pair.pad1", pairBase, offsetof(BvhPair, pad1));
    expectOffset("params.seed", 0, offsetof(RenderParams, seed));
    expectOffset("params.cameraRight", 0, offsetof(RenderParams, cameraRight));
    expectOffset("params.maxDepth", 0, offsetof(RenderParams, maxDepth));
    expectOffset("params.pathCapacity", 0, offsetof(RenderParams, pathCapacity));
    expectOffset("params.sceneCenter", 0, offsetof(RenderParams, sceneCenter));
    expectOffset("params.sceneRadius", 0, offsetof(RenderParams, sceneRadius));
    expectOffset("params.clampRadiance", 0, offsetof(RenderParams, clampRadiance));
    expectOffset("light.direction", 0, offsetof(PunctualLight, direction));
    expectOffset("light.intensity", 0, offsetof(PunctualLight, intensity));
    expectOffset("light.emitter", 0, offsetof(PunctualLight, emitter));
    expectOffset("light.pad2", 0, offsetof(PunctualLight, pad2));
    // B3: texture references and per-triangle vertex data (texture_types.h).
    expectOffset("tref.page", 0, offsetof(TextureRef, page));
    expectOffset("tref.vRow", 0, offsetof(TextureRef, vRow));
    expectOffset("tref.offset", 0, offsetof(TextureRef, offset));
    expectOffset("tref.flags", 0, offsetof(TextureRef, flags));
    expectOffset("tnorm.n2", sizeof(TextureRef), offsetof(TriangleNormals, n2));
    const size_t tangentBase = sizeof(TextureRef) + sizeof(TriangleNormals);
    expectOffset("ttan.signs", tangentBase, offsetof(TriangleTangents, signs));
    // An array of TriangleUvs: the std430 stride must equal sizeof (24, no padding to 16).
    const size_t uvBase = tangentBase + sizeof(TriangleTangents);
    expectOffset("tuv[1].uv2", uvBase, sizeof(TriangleUvs) + offsetof(TriangleUvs, uv2));
    const size_t countersBase = 0;
    expectOffset("counters.rayArgs.count", countersBase,
                 offsetof(QueueCounters, rayArgs) + offsetof(DispatchArgs, count));
    expectOffset("counters.shadowArgs.groupsX", countersBase, offsetof(QueueCounters, shadowArgs));
    expectOffset("counters.nonFiniteSamples", countersBase,
                 offsetof(QueueCounters, nonFiniteSamples));
    expectOffset("counters.depthRays", countersBase, offsetof(QueueCounters, depthRays));
    expectOffset("counters.depthShadowRays", countersBase,
                 offsetof(QueueCounters, depthShadowRays));
    expectOffset("counters.kindCount", countersBase, offsetof(QueueCounters, kindCount));
    expectOffset("counters.kindArgs[0].groupsX", countersBase, offsetof(QueueCounters, kindArgs));
    expectOffset("counters.kindArgs[2].count", countersBase,
                 offsetof(QueueCounters, kindArgs) + 2 * sizeof(DispatchArgs) +
                     offsetof(DispatchArgs, count));
}

} // namespace
} // namespace wf

namespace {

// Every binding of the shared descriptor set, with the pages a paged table takes after its
// first: no two may share a number (vcm's first bindings once took the vertex colours').
TEST(SharedLayout, BindingNumbersAreDistinct) {
    struct Range {
        const char* name;
        int first;
        int count;
    };
    const Range ranges[] = {
        {"TRIANGLES", WF_BINDING_TRIANGLES, 1}, {"BVH_NODES", WF_BINDING_BVH_NODES, 1},
        {"MATERIALS", WF_BINDING_MATERIALS, 1}, {"EMITTERS", WF_BINDING_EMITTERS, 1},
        {"INSTANCES", WF_BINDING_INSTANCES, 1}, {"PARAMS", WF_BINDING_PARAMS, 1},
        {"COUNTERS", WF_BINDING_COUNTERS, 1}, {"FILM", WF_BINDING_FILM, 1},
        {"RAY_ORIGIN", WF_BINDING_RAY_ORIGIN, 1}, {"RAY_DIRECTION", WF_BINDING_RAY_DIRECTION, 1},
        {"THROUGHPUT", WF_BINDING_THROUGHPUT, 1}, {"RADIANCE", WF_BINDING_RADIANCE, 1},
        {"HITS", WF_BINDING_HITS, 1}, {"SHADOW_ORIGIN", WF_BINDING_SHADOW_ORIGIN, 1},
        {"SHADOW_DIRECTION", WF_BINDING_SHADOW_DIRECTION, 1},
        {"SHADOW_RADIANCE", WF_BINDING_SHADOW_RADIANCE, 1},
        {"RAY_QUEUES", WF_BINDING_RAY_QUEUES, 1}, {"LIGHT_TREE", WF_BINDING_LIGHT_TREE, 1},
        {"LIGHT_TREE_TRAILS", WF_BINDING_LIGHT_TREE_TRAILS, 1},
        {"AOV_PATHS", WF_BINDING_AOV_PATHS, 1}, {"AOV_FILM", WF_BINDING_AOV_FILM, 1},
        {"MOMENT_FILM", WF_BINDING_MOMENT_FILM, 1},
        {"ACTIVE_PIXELS", WF_BINDING_ACTIVE_PIXELS, 1},
        {"REPLICATE_FILM", WF_BINDING_REPLICATE_FILM, 1}, {"RAY_CONES", WF_BINDING_RAY_CONES, 1},
        {"RAY_CONE_TEXELS", WF_BINDING_RAY_CONE_TEXELS, 1},
        {"TRIANGLE_PAGE1", WF_BINDING_TRIANGLE_PAGE1, 7},
        {"BVH_PAGE1", WF_BINDING_BVH_PAGE1, 7}, {"INSTANCE_PAGE1", WF_BINDING_INSTANCE_PAGE1, 7},
        {"KIND_QUEUES", WF_BINDING_KIND_QUEUES, 1},
        {"KIND_QUEUE_TEXELS", WF_BINDING_KIND_QUEUE_TEXELS, 1},
        {"TOP_LEVEL", WF_BINDING_TOP_LEVEL, 1}, {"MOTION_KEYS", WF_BINDING_MOTION_KEYS, 1},
        {"RAY_TIME", WF_BINDING_RAY_TIME, 1}, {"LIGHT_FILM", WF_BINDING_LIGHT_FILM, 1},
        {"PATH_MIS", WF_BINDING_PATH_MIS, 1}, {"LIGHT_DEPTHS", WF_BINDING_LIGHT_DEPTHS, 1},
        {"LIGHT_VERTEX_HITS", WF_BINDING_LIGHT_VERTEX_HITS, 1},
        {"LIGHT_VERTEX_DIRECTIONS", WF_BINDING_LIGHT_VERTEX_DIRECTIONS, 1},
        {"LIGHT_VERTEX_THROUGHPUTS", WF_BINDING_LIGHT_VERTEX_THROUGHPUTS, 1},
        {"LIGHT_VERTEX_POSITIONS", WF_BINDING_LIGHT_VERTEX_POSITIONS, 1},
        {"MERGE_LISTS", WF_BINDING_MERGE_LISTS, 1}, {"GUIDE_PARAMS", WF_BINDING_GUIDE_PARAMS, 1},
        {"GUIDE_SPATIAL", WF_BINDING_GUIDE_SPATIAL, 1},
        {"GUIDE_SAMPLING", WF_BINDING_GUIDE_SAMPLING, 1},
        {"GUIDE_BUILDING", WF_BINDING_GUIDE_BUILDING, 1},
        {"GUIDE_SPLATS", WF_BINDING_GUIDE_SPLATS, 1},
        {"GUIDE_LEAF_SAMPLES", WF_BINDING_GUIDE_LEAF_SAMPLES, 1},
        {"GUIDE_RECORDS", WF_BINDING_GUIDE_RECORDS, 1},
        {"GUIDE_COUNTS", WF_BINDING_GUIDE_COUNTS, 1}, {"LIGHTS", WF_BINDING_LIGHTS, 1},
        {"ENVIRONMENT", WF_BINDING_ENVIRONMENT, 1},
        {"ENVIRONMENT_ALIAS", WF_BINDING_ENVIRONMENT_ALIAS, 1},
        {"RAY_ORIGIN_TEXELS", WF_BINDING_RAY_ORIGIN_TEXELS, 1},
        {"RAY_DIRECTION_TEXELS", WF_BINDING_RAY_DIRECTION_TEXELS, 1},
        {"THROUGHPUT_TEXELS", WF_BINDING_THROUGHPUT_TEXELS, 1},
        {"RADIANCE_TEXELS", WF_BINDING_RADIANCE_TEXELS, 1},
        {"HITS_TEXELS", WF_BINDING_HITS_TEXELS, 1},
        {"SHADOW_ORIGIN_TEXELS", WF_BINDING_SHADOW_ORIGIN_TEXELS, 1},
        {"SHADOW_DIRECTION_TEXELS", WF_BINDING_SHADOW_DIRECTION_TEXELS, 1},
        {"SHADOW_RADIANCE_TEXELS", WF_BINDING_SHADOW_RADIANCE_TEXELS, 1},
        {"RAY_QUEUE_TEXELS", WF_BINDING_RAY_QUEUE_TEXELS, 1},
        {"TEXTURE_REFS", WF_BINDING_TEXTURE_REFS, 1}, {"NORMALS", WF_BINDING_NORMALS, 1},
        {"TANGENTS", WF_BINDING_TANGENTS, 1}, {"TEXCOORDS0", WF_BINDING_TEXCOORDS0, 1},
        {"TEXCOORDS1", WF_BINDING_TEXCOORDS1, 1}, {"TEXELS0", WF_BINDING_TEXELS0, 4},
        {"NORMAL_PAGE1", WF_BINDING_NORMAL_PAGE1, 7},
        {"TANGENT_PAGE1", WF_BINDING_TANGENT_PAGE1, 7},
        {"TEXCOORD0_PAGE1", WF_BINDING_TEXCOORD0_PAGE1, 7},
        {"TEXCOORD1_PAGE1", WF_BINDING_TEXCOORD1_PAGE1, 7},
        {"VERTEX_COLORS", WF_BINDING_VERTEX_COLORS, 1},
        {"VERTEX_COLOR_PAGE1", WF_BINDING_VERTEX_COLOR_PAGE1, 7},
        {"SAMPLER_TABLES", WF_BINDING_SAMPLER_TABLES, 1},
        {"PATH_WAVELENGTH", WF_BINDING_PATH_WAVELENGTH, 1},
    };
    std::map<int, std::string> owner;
    for (const Range& r : ranges)
        for (int b = r.first; b < r.first + r.count; ++b) {
            const auto [it, fresh] = owner.emplace(b, r.name);
            EXPECT_TRUE(fresh) << "binding " << b << ": " << r.name << " and " << it->second;
        }
}

} // namespace
