// The glTF material extensions on the GPU: a scene without them compiles none of their code;
// KHR_materials_volume's Beer-Lambert attenuation through an index-matched box of absorbing
// glass equals exp(-sigma_a L) x background; the KHR_materials_specular textures scale the
// factors; coated and sheened spheres in the white furnace never outshine the environment.
// (The layers' own textures: test_layer_textures.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_materials.h"

namespace wf::test {
namespace {

bool spirvMentions(const std::vector<uint32_t>& spirv, const char* name) {
    const char* bytes = reinterpret_cast<const char*>(spirv.data());
    return std::string(bytes, spirv.size() * 4).find(name) != std::string::npos;
}

std::string defineValue(const ShaderDefines& defines, const std::string& name) {
    for (const auto& [key, value] : defines)
        if (key == name)
            return value;
    return "(absent)";
}

RenderSettings settings(uint32_t size, uint32_t spp, uint32_t depth) {
    RenderSettings s;
    s.width = s.height = size;
    s.samplesPerPixel = spp;
    s.maxDepth = depth;
    return s;
}

void uniformSky(Scene& scene, float radiance) {
    scene.environment = rowEnvironment(1, 1, nullptr);
    scene.environment.rgb = {radiance, radiance, radiance};
}

// An axis-aligned box [lo, hi], counter-clockwise seen from outside.
void addBox(Scene& scene, glm::vec3 lo, glm::vec3 hi, uint32_t material) {
    const glm::vec3 c = 0.5f * (lo + hi), e = 0.5f * (hi - lo);
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f), u(0.0f), v(0.0f);
            n[axis] = sign;
            u[(axis + 1) % 3] = e[(axis + 1) % 3];
            v[(axis + 2) % 3] = e[(axis + 2) % 3];
            if (sign < 0.0f)
                std::swap(u, v); // keep cross(u, v) along n
            const glm::vec3 f = c + n * e[axis];
            const glm::vec3 a = f - u - v, b = f + u - v, d = f + u + v, g = f - u + v;
            scene.triangles.push_back({a, material, b, WF_NO_EMITTER, d, 0});
            scene.triangles.push_back({a, material, d, WF_NO_EMITTER, g, 0});
        }
}

// Clear, index-matched glass (ior 1, no specular layer: the boundary is invisible) absorbing
// with sigma_a per unit length, thicknessFactor `thickness` (0: thin-walled).
Material absorbingGlass(glm::vec3 sigma, float thickness) {
    Material m = gltf::defaultMaterial();
    m.baseColor = glm::vec4(1.0f);
    m.roughness = 0.0f;
    m.transmission = 1.0f;
    m.ior = 1.0f;
    m.specular = 0.0f;
    m.attenuation = sigma;
    m.thickness = thickness;
    return m;
}

// A unit box at the origin, seen along -z through its front and back faces by a narrow camera,
// under a uniform sky of radiance 1: a ray at angle theta to the axis crosses L = 1 / cos theta.
Scene absorbingBox(const Material& glass) {
    Scene scene;
    scene.materials.push_back(glass);
    addBox(scene, glm::vec3(-0.5f), glm::vec3(0.5f), 0);
    uniformSky(scene, 1.0f);
    scene.camera.position = glm::vec3(0.0f, 0.0f, 4.0f);
    scene.camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
    scene.camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
    scene.camera.yfov = 0.1f; // every ray crosses the front and back faces
    scene.hasCamera = true;
    return scene;
}

TEST(MaterialLayers, SceneWithoutThemCompilesNoneOfTheirCode) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf");
    PreparedScene prepared = prepareScene(std::move(scene));
    ShaderCompiler compiler(defaultShaderDir(), "");
    WavefrontRenderer renderer(gpuContext(), prepared, settings(8, 1, 2), compiler);
    const ShaderDefines& defines = renderer.shaderDefines();
    for (const char* name :
         {"WF_HAS_CLEARCOAT", "WF_HAS_SHEEN", "WF_HAS_VOLUME", "WF_HAS_SPECULAR_TEXTURES",
          "WF_HAS_IRIDESCENCE", "WF_HAS_CLEARCOAT_TEXTURES", "WF_HAS_CLEARCOAT_NORMAL_MAPS",
          "WF_HAS_SHEEN_TEXTURES", "WF_HAS_THICKNESS_TEXTURES"})
        EXPECT_EQ(defineValue(defines, name), "0") << name;
    const char* layerCode[] = {"layeredSample", "coatReflection", "sheenLobe", "sheenAlbedoNode",
                               "absorption", "fresnelIridescence", "frontCoatNormal",
                               "toCoatFrame"};
    for (const char* pass : {"shade.comp", "megakernel.comp"}) {
        const std::vector<uint32_t> spirv = compiler.compile(pass, defines).spirv;
        for (const char* name : layerCode)
            EXPECT_FALSE(spirvMentions(spirv, name)) << pass << " has " << name;
    }
    // Each switch brings its own code and only that (so the check above can fail).
    auto with = [&](std::initializer_list<const char*> names) {
        ShaderDefines on = defines;
        for (auto& [key, value] : on)
            for (const char* name : names)
                if (key == name)
                    value = "1";
        return compiler.compile("shade.comp", on).spirv;
    };
    const std::vector<uint32_t> coat = with({"WF_HAS_CLEARCOAT"}), sheen = with({"WF_HAS_SHEEN"}),
                                volume = with({"WF_HAS_VOLUME"}),
                                film = with({"WF_HAS_IRIDESCENCE"});
    EXPECT_TRUE(spirvMentions(coat, "coatReflection"));
    EXPECT_FALSE(spirvMentions(coat, "sheenLobe"));
    EXPECT_TRUE(spirvMentions(sheen, "sheenLobe"));
    EXPECT_FALSE(spirvMentions(sheen, "coatReflection"));
    EXPECT_TRUE(spirvMentions(volume, "absorption"));
    EXPECT_FALSE(spirvMentions(volume, "layeredSample"));
    EXPECT_TRUE(spirvMentions(film, "fresnelIridescence"));
    EXPECT_FALSE(spirvMentions(film, "layeredSample"));
    // The layers' textures (issue 48): each switch changes the code of a textured variant with
    // its layer, the coat's normal map bringing its own frame; none is in the plain coat.
    EXPECT_FALSE(spirvMentions(coat, "toCoatFrame"));
    const std::vector<uint32_t> texturedCoat = with({"WF_HAS_CLEARCOAT", "WF_HAS_TEXTURES"});
    EXPECT_NE(with({"WF_HAS_CLEARCOAT", "WF_HAS_TEXTURES", "WF_HAS_CLEARCOAT_TEXTURES"}),
              texturedCoat);
    const std::vector<uint32_t> coatMaps =
        with({"WF_HAS_CLEARCOAT", "WF_HAS_TEXTURES", "WF_HAS_NORMALS", "WF_HAS_NORMAL_MAPS",
              "WF_HAS_CLEARCOAT_NORMAL_MAPS"});
    EXPECT_TRUE(spirvMentions(coatMaps, "frontCoatNormal"));
    EXPECT_TRUE(spirvMentions(coatMaps, "toCoatFrame"));
    EXPECT_NE(with({"WF_HAS_SHEEN", "WF_HAS_TEXTURES", "WF_HAS_SHEEN_TEXTURES"}),
              with({"WF_HAS_SHEEN", "WF_HAS_TEXTURES"}));
    EXPECT_NE(with({"WF_HAS_VOLUME", "WF_HAS_TEXTURES", "WF_HAS_THICKNESS_TEXTURES"}),
              with({"WF_HAS_VOLUME", "WF_HAS_TEXTURES"}));
    // Every switch at once, in both shading passes (the host builds such variants too).
    ShaderDefines all = defines;
    for (auto& [key, value] : all)
        if (key == "WF_HAS_CLEARCOAT" || key == "WF_HAS_SHEEN" || key == "WF_HAS_VOLUME" ||
            key == "WF_HAS_SPECULAR_TEXTURES" || key == "WF_HAS_TEXTURES" ||
            key == "WF_HAS_IRIDESCENCE" || key == "WF_HAS_CLEARCOAT_TEXTURES" ||
            key == "WF_HAS_CLEARCOAT_NORMAL_MAPS" || key == "WF_HAS_SHEEN_TEXTURES" ||
            key == "WF_HAS_THICKNESS_TEXTURES" || key == "WF_HAS_NORMALS" ||
            key == "WF_HAS_NORMAL_MAPS")
            value = "1";
    for (const char* pass : {"shade.comp", "megakernel.comp"})
        EXPECT_TRUE(spirvMentions(compiler.compile(pass, all).spirv, "layeredSample")) << pass;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(MaterialLayers, VolumeAttenuationIsBeerLambert) {
    // attenuationColor (0.5, 0.25, 0.8) at attenuationDistance 1.
    const glm::vec3 sigma(-std::log(0.5f), -std::log(0.25f), -std::log(0.8f));
    const uint32_t size = 16;
    // The longest ray, through the image's corner: L = 1 / cos(theta) with tan(theta) = sqrt(2)
    // tan(yfov / 2), the image being square.
    const double tanCorner = std::sqrt(2.0) * std::tan(0.05);
    const double longest = std::sqrt(1.0 + tanCorner * tanCorner);
    for (bool megakernel : {false, true}) {
        RenderSettings s = settings(size, 4, 5);
        s.megakernel = megakernel;
        RenderResult r = renderScene(absorbingBox(absorbingGlass(sigma, 1.0f)), s);
        EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
        double mean[3] = {0, 0, 0};
        for (uint32_t p = 0; p < size * size; ++p)
            for (int c = 0; c < 3; ++c) {
                const float value = r.rgb[3 * p + c];
                EXPECT_LE(value, std::exp(-sigma[c]) + 1e-4) << "pixel " << p << " channel " << c;
                EXPECT_GE(value, std::exp(-sigma[c] * longest) - 1e-4)
                    << "pixel " << p << " channel " << c;
                mean[c] += value / (size * size);
            }
        std::printf("volume %s: %.5f %.5f %.5f (exp(-sigma L) on the axis %.5f %.5f %.5f)\n",
                    megakernel ? "megakernel" : "wavefront", mean[0], mean[1], mean[2],
                    std::exp(-sigma[0]), std::exp(-sigma[1]), std::exp(-sigma[2]));
    }
    // Thin-walled (thicknessFactor 0): no path length inside, no attenuation.
    RenderResult thin = renderScene(absorbingBox(absorbingGlass(sigma, 0.0f)), settings(8, 2, 5));
    for (float value : thin.rgb)
        EXPECT_NEAR(value, 1.0f, 1e-4f);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// A black dielectric shows only its specular layer: a 2x1 specular map (nearest) whose left
// texel has A = 0 turns it off exactly; the right one has A = 1 and a red specularColorTexture
// texel, which scales F0 only (F90 stays 1, as glTF says): red reflects more than green and
// blue, which agree.
TEST(MaterialLayers, SpecularTexturesScaleTheFactors) {
    Scene scene;
    Material m = gltf::defaultMaterial();
    m.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    m.roughness = 0.4f;
    m.specular = 1.0f;
    m.specularTexture = 0;
    m.specularColorTexture = 1;
    scene.materials.push_back(m);
    const glm::vec3 a(-0.5f, -0.5f, -1.0f), b(0.5f, -0.5f, -1.0f), c(0.5f, 0.5f, -1.0f),
        d(-0.5f, 0.5f, -1.0f);
    scene.triangles.push_back({a, 0, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, 0, c, WF_NO_EMITTER, d, 0});
    scene.surface.uv0.push_back({{0, 1}, {1, 1}, {1, 0}});
    scene.surface.uv0.push_back({{0, 1}, {1, 0}, {0, 0}});
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0x00ffffffu, 0xff0000ffu}; // white with A = 0 | red with A = 1
    scene.surface.images.push_back(image);
    for (uint32_t flags : {0u, WF_TEXTURE_SRGB}) {
        TextureRef ref{};
        ref.uRow = glm::vec3(1, 0, 0);
        ref.vRow = glm::vec3(0, 1, 0);
        ref.flags = flags | WF_TEXTURE_NEAREST;
        scene.surface.textureRefs.push_back(ref);
        scene.surface.refImage.push_back(0);
    }
    uniformSky(scene, 1.0f);
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.forward = glm::vec3(0, 0, -1);
    scene.camera.up = glm::vec3(0, 1, 0);
    scene.camera.yfov = 2.0f * std::atan(0.5f);
    scene.hasCamera = true;
    const uint32_t size = 16;
    RenderResult r = renderScene(scene, settings(size, 16, 2));
    double left[3] = {0, 0, 0}, right[3] = {0, 0, 0};
    for (uint32_t y = 2; y < size - 2; ++y)
        for (uint32_t x = 2; x < size / 2 - 1; ++x)
            for (int k = 0; k < 3; ++k) {
                left[k] = std::max(left[k], double(r.rgb[3 * (y * size + x) + k]));
                right[k] += r.rgb[3 * (y * size + x + size / 2 + 1) + k];
            }
    for (int k = 0; k < 3; ++k)
        EXPECT_EQ(left[k], 0.0) << "specularTexture A = 0 must leave nothing, channel " << k;
    EXPECT_GT(right[0] / (12 * 5), 0.02);
    EXPECT_GT(right[0], 1.5 * right[1]);
    EXPECT_GT(right[1], 0.0);
    EXPECT_NEAR(right[1], right[2], 1e-6 * right[1]);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The white furnace on the GPU with coat and sheen at full strength over white bases: nothing
// brighter than the environment, whichever estimator.
TEST(MaterialLayers, CoatAndSheenInTheWhiteFurnace) {
    Material coat = gltf::defaultMaterial();
    coat.baseColor = glm::vec4(1.0f);
    coat.specular = 1.0f;
    coat.roughness = 0.5f;
    coat.clearcoat = 1.0f;
    coat.clearcoatRoughness = 0.1f;
    Material sheen = gltf::defaultMaterial();
    sheen.baseColor = glm::vec4(1.0f);
    sheen.sheenColor = glm::vec3(1.0f);
    sheen.sheenRoughness = 0.3f;
    for (const Material& m : {coat, sheen}) {
        for (LightSampling sampling : {LightSampling::Bsdf, LightSampling::Mis}) {
            RenderSettings s = settings(16, 32, 32);
            s.lightSampling = sampling;
            s.seed = 5;
            RenderResult r = renderScene(furnaceSphere(m, 1.0f), s);
            EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
            MeanAndError e = imageMean(r.rgb);
            EXPECT_LE(e.mean, 1.0 + 4.0 * e.standardError + 2e-3)
                << (m.clearcoat > 0 ? "coat" : "sheen") << " " << lightSamplingName(sampling);
            EXPECT_GT(e.mean, 0.8); // and the layers do not swallow the light either
            std::printf("furnace %s %s: %.4f +- %.4f\n", m.clearcoat > 0 ? "coat" : "sheen",
                        lightSamplingName(sampling), e.mean, e.standardError);
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
