// KHR_materials_diffuse_transmission on the GPU (lavapipe, validation on): a thin sheet lit by
// a point light behind it glows on the camera's side exactly as bsdf.h evaluated on the CPU
// predicts (and lit from the front, reflects the rest), with the colour texture read in sRGB;
// lights behind the sheet are reached by next-event estimation, the only strategy that finds a
// point light, and the light tree picks lights on both sides of it; light tracing and BDPT
// agree with the path tracer through the sheet; a white diffuse-transmitting sphere in the
// furnace vanishes when lossless and never outshines it; scenes without the extension compile
// none of it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "mini_gltf.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"
#include "shaders/bsdf/bsdf.h"

namespace wf::test {
namespace {

constexpr float HALF = 1.5f; // the sheet and the orthographic view: [-1.5, 1.5]^2
constexpr float LIGHT_DISTANCE = 1.0f;
constexpr uint32_t SIZE = 48;
const glm::vec3 BASE(0.8f, 0.6f, 0.4f);
const glm::vec3 COLOUR(0.9f, 0.7f, 0.3f);
constexpr float FACTOR = 0.6f;
constexpr float ROUGHNESS = 0.5f;
// A 1x1 PNG of RGB (128, 255, 191), the colour texture (sRGB).
const char* TEXEL_PNG = "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGNo+L8fAARBAj8"
                        "UxVG+AAAAAElFTkSuQmCC";

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

glm::vec3 texelColour() {
    return glm::vec3(srgbToLinear(128.0f / 255.0f), 1.0f, srgbToLinear(191.0f / 255.0f));
}

struct Sheet {
    const char* name;
    float lightY;     // the point light at (0, lightY, 0): below the sheet is behind it
    bool texture;     // diffuseTransmissionColorTexture = TEXEL_PNG
    bool perspective; // a pinhole camera (light tracing needs a lens), else orthographic
    bool twoLights = false; // a second light on the other side, at (0.7, -lightY, -0.4)
};

// A quad at y = 0 facing +y (the camera's side), the camera above looking down, one point
// light of intensity 1.
std::string sheetGltf(const TempDir& dir, const Sheet& s) {
    MiniGltf g;
    const std::vector<float> corners = {-HALF, 0, -HALF, HALF, 0, -HALF,
                                        HALF,  0, HALF,  -HALF, 0, HALF};
    const int pos = g.addPositions(corners);
    const std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    const std::vector<float> uvs = {0, 0, 1, 0, 1, 1, 0, 1};
    const int normal = g.addAccessor(g.addView(normals.data(), 48), F32, 4, "VEC3");
    const int uv = g.addAccessor(g.addView(uvs.data(), 32), F32, 4, "VEC2");
    g.addMesh(pos, g.addIndices<uint16_t>({0, 2, 1, 0, 3, 2}, U16), 0, 4,
              ",\"NORMAL\":" + std::to_string(normal) + ",\"TEXCOORD_0\":" + std::to_string(uv));
    char material[512];
    std::snprintf(material, sizeof material,
                  R"({"pbrMetallicRoughness":{"baseColorFactor":[%g,%g,%g,1],"metallicFactor":0,)"
                  R"("roughnessFactor":%g},"extensions":{"KHR_materials_diffuse_transmission":{)"
                  R"("diffuseTransmissionFactor":%g,"diffuseTransmissionColorFactor":[%g,%g,%g])",
                  BASE.x, BASE.y, BASE.z, ROUGHNESS, FACTOR, COLOUR.x, COLOUR.y, COLOUR.z);
    g.materials.push_back(std::string(material) +
                          (s.texture ? R"(,"diffuseTransmissionColorTexture":{"index":0})" : "") +
                          "}}}");
    if (s.texture) {
        g.images.push_back(std::string(R"({"uri":"data:image/png;base64,)") + TEXEL_PNG + "\"}");
        g.textures.push_back(R"({"source":0})");
    }
    g.cameras.push_back(
        s.perspective
            ? R"({"type":"perspective","perspective":{"yfov":0.8,"znear":0.05,"zfar":100}})"
            : R"({"type":"orthographic","orthographic":{"xmag":1.5,"ymag":1.5,)"
              R"("znear":0.1,"zfar":100}})");
    char light[128];
    std::snprintf(light, sizeof light,
                  R"({"extensions":{"KHR_lights_punctual":{"light":0}},"translation":[0,%g,0]})",
                  s.lightY);
    g.nodes = {R"({"mesh":0})",
               std::string(R"({"camera":0,"translation":[0,)") + (s.perspective ? "2.5" : "5") +
                   R"(,0],"rotation":[-0.70710678,0,0,0.70710678]})",
               light};
    g.scenes = R"([{"nodes":[0,1,2]}])";
    if (s.twoLights) {
        std::snprintf(light, sizeof light,
                      R"({"extensions":{"KHR_lights_punctual":{"light":0}},)"
                      R"("translation":[0.7,%g,-0.4]})",
                      -s.lightY);
        g.nodes.push_back(light);
        g.scenes = R"([{"nodes":[0,1,2,3]}])";
    }
    g.extra = R"(,"extensionsUsed":["KHR_materials_diffuse_transmission","KHR_lights_punctual"],)"
              R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","intensity":1}]}})";
    return g.write(dir);
}

// What bsdf.h gives each pixel of the orthographic view (4x4 points across it): radiance
// f(up, toLight) I |cos| / d^2, the light's side choosing reflection or transmission.
std::vector<glm::vec3> expectedImage(const Sheet& s) {
    gpu_types::BsdfParams m{BASE, 0.0f, ROUGHNESS, 1.5f, 0.0f, 1.0f, glm::vec3(1.0f)};
    m.diffuseTransmission = FACTOR;
    m.diffuseTransmissionColor = COLOUR * (s.texture ? texelColour() : glm::vec3(1.0f));
    auto local = [](glm::vec3 w) { return glm::vec3(w.x, w.z, w.y); };
    std::vector<glm::vec3> image(SIZE * SIZE, glm::vec3(0.0f));
    for (uint32_t r = 0; r < SIZE; ++r)
        for (uint32_t col = 0; col < SIZE; ++col) {
            glm::dvec3 sum(0.0);
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    const float x = -HALF + 2.0f * HALF * (col + (j + 0.5f) / 4.0f) / SIZE;
                    const float z = -HALF + 2.0f * HALF * (r + (i + 0.5f) / 4.0f) / SIZE;
                    const glm::vec3 toLight(-x, s.lightY, -z);
                    const float d2 = glm::dot(toLight, toLight);
                    const glm::vec3 wi = toLight / std::sqrt(d2);
                    sum += glm::dvec3(gpu_types::bsdfEval(m, glm::vec3(0, 0, 1), local(wi)) *
                                      (std::abs(wi.y) / d2));
                }
            image[r * SIZE + col] = glm::vec3(sum / 16.0);
        }
    return image;
}

RenderSettings sheetSettings(Integrator integrator, uint32_t spp, uint32_t seed) {
    RenderSettings settings;
    settings.width = settings.height = SIZE;
    settings.samplesPerPixel = spp;
    settings.maxDepth = 2; // direct light only: through the sheet, or off it
    settings.seed = seed;
    settings.integrator = integrator;
    return settings;
}

TEST(DiffuseTransmission, SheetLitFromBehindGlowsAsTheBsdfSays) {
    const Sheet sheets[] = {
        {"lit from behind", -LIGHT_DISTANCE, false, false},
        {"lit from behind, colour texture", -LIGHT_DISTANCE, true, false},
        {"lit from the front", LIGHT_DISTANCE, false, false},
    };
    for (const Sheet& s : sheets) {
        TempDir dir;
        const RenderResult result =
            renderScene(loadGltf(sheetGltf(dir, s)), sheetSettings(Integrator::Path, 16, 5));
        const std::vector<glm::vec3> expected = expectedImage(s);
        glm::dvec3 diff(0.0), total(0.0), mean(0.0);
        for (uint32_t i = 0; i < SIZE * SIZE; ++i)
            for (int k = 0; k < 3; ++k) {
                diff[k] += std::abs(result.rgb[3 * i + k] - expected[i][k]);
                total[k] += expected[i][k];
                mean[k] += result.rgb[3 * i + k];
            }
        const double pixels = SIZE * SIZE;
        std::printf("diffuse transmission %-32s mean (%.4f %.4f %.4f), expected (%.4f %.4f "
                    "%.4f)\n",
                    s.name, mean.x / pixels, mean.y / pixels, mean.z / pixels, total.x / pixels,
                    total.y / pixels, total.z / pixels);
        for (int k = 0; k < 3; ++k) {
            ASSERT_GT(total[k], 0.0) << s.name;
            EXPECT_LT(diff[k] / total[k], 0.02) << s.name << " channel " << k;
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// Light subpaths leave the point light, cross the sheet by the Lambert lobe and connect to the
// lens; BDPT weighs that against NEE. Both estimate the path tracer's image (its mean within
// a few standard errors, from the spread over seeds).
TEST(DiffuseTransmission, LightTracingAndBdptAgreeThroughTheSheet) {
    for (float lightY : {-LIGHT_DISTANCE, LIGHT_DISTANCE}) { // behind the sheet, and in front
        TempDir dir;
        const Scene scene =
            loadGltf(sheetGltf(dir, {"perspective", lightY, lightY < 0.0f, true}));
        const double path =
            imageMean(renderScene(scene, sheetSettings(Integrator::Path, 64, 1)).rgb).mean;
        ASSERT_GT(path, 0.01);
        for (Integrator integrator : {Integrator::Light, Integrator::Bdpt}) {
            double sum = 0.0, sum2 = 0.0;
            const int seeds = 6;
            for (int seed = 0; seed < seeds; ++seed) {
                const RenderResult r =
                    renderScene(scene, sheetSettings(integrator, 64, 140 + seed));
                EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
                const double m = imageMean(r.rgb).mean;
                sum += m;
                sum2 += m * m;
            }
            const double mean = sum / seeds;
            const double error =
                std::sqrt(std::max(sum2 / seeds - mean * mean, 0.0) / (seeds - 1));
            std::printf("diffuse transmission, light at y %g: %s %.5f +- %.5f, path %.5f\n",
                        lightY, integratorName(integrator), mean, error, path);
            EXPECT_NEAR(mean, path, 5.0 * error + 0.003 * path) << integratorName(integrator);
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The light tree weighs lights by the side they light a receiver from; a diffuse-transmitting
// surface receives from both, so the tree's choice (a light on each side of the sheet) gives
// the image that choosing by power does.
TEST(DiffuseTransmission, LightTreeReachesLightsBehindTheSheet) {
    TempDir dir;
    const Scene scene =
        loadGltf(sheetGltf(dir, {"a light on each side", -LIGHT_DISTANCE, false, false, true}));
    MeanAndError means[2];
    for (int tree = 0; tree < 2; ++tree) {
        RenderSettings settings = sheetSettings(Integrator::Path, 64, 9);
        settings.lightSelection = tree ? LightSelection::Tree : LightSelection::Power;
        const RenderResult r = renderScene(scene, settings);
        EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
        means[tree] = imageMean(r.rgb);
    }
    std::printf("diffuse transmission, a light on each side: power %.5f +- %.5f, tree %.5f +- "
                "%.5f\n",
                means[0].mean, means[0].standardError, means[1].mean, means[1].standardError);
    ASSERT_GT(means[0].mean, 0.01);
    EXPECT_NEAR(means[1].mean, means[0].mean,
                4.0 * std::hypot(means[0].standardError, means[1].standardError) +
                    0.002 * means[0].mean);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

gpu_types::Material translucent(float specular, float roughness, float factor,
                                float transmission = 0.0f, float thickness = 0.0f) {
    gpu_types::Material m{};
    m.baseColor = glm::vec4(1.0f);
    m.roughness = roughness;
    m.ior = 1.5f;
    m.transmission = transmission;
    m.specular = specular;
    m.specularColor = glm::vec3(1.0f);
    m.thickness = thickness;
    m.attenuation = glm::vec3(thickness > 0.0f ? 0.5f : 0.0f);
    m.diffuseTransmission = factor;
    m.diffuseTransmissionColor = glm::vec3(1.0f);
    m.diffuseTransmissionTexture = m.diffuseTransmissionColorTexture = WF_NO_TEXTURE;
    return m;
}

// The white furnace of test_material_furnace.cpp: a white Lambert base split in half, without
// the specular layer, loses nothing (light crosses the sphere's shell and leaves it again) and
// vanishes; under the layer, beside rough glass, nothing outshines the environment.
TEST(DiffuseTransmission, WhiteFurnace) {
    struct Case {
        const char* name;
        gpu_types::Material material;
        bool lossless;
    };
    const Case cases[] = {
        {"white Lambert split in half", translucent(0.0f, 1.0f, 0.5f), true},
        {"white Lambert, all through", translucent(0.0f, 1.0f, 1.0f), true},
        {"under the layer, 0.4", translucent(1.0f, 0.4f, 0.7f), false},
        {"beside rough glass", translucent(1.0f, 0.3f, 0.5f, 0.5f), false},
        {"absorbing inside", translucent(0.0f, 1.0f, 0.5f, 0.0f, 1.0f), false},
    };
    for (const Case& c : cases) {
        for (LightSampling sampling : {LightSampling::Bsdf, LightSampling::Mis}) {
            RenderSettings settings;
            settings.width = settings.height = 24;
            settings.samplesPerPixel = 64;
            settings.maxDepth = 64;
            settings.lightSampling = sampling;
            settings.seed = 79;
            const RenderResult result = renderScene(furnaceSphere(c.material, 1.0f), settings);
            EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
            const MeanAndError m = imageMean(result.rgb);
            std::printf("diffuse transmission furnace %-28s %-4s %.4f +- %.4f\n", c.name,
                        lightSamplingName(sampling), m.mean, m.standardError);
            EXPECT_LE(m.mean, 1.0 + 4.0 * m.standardError + 2e-3) << c.name;
            EXPECT_GT(m.mean, 0.3) << c.name;
            if (c.lossless)
                EXPECT_NEAR(m.mean, 1.0, 4.0 * m.standardError + 2e-3) << c.name;
            else if (c.material.thickness > 0.0f) // Beer-Lambert takes its share inside
                EXPECT_LT(m.mean, 0.98) << c.name;
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// WF_HAS_DIFFUSE_TRANSMISSION is defined only for scenes that use it.
TEST(DiffuseTransmission, DefinedOnlyForScenesThatUseIt) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    RenderSettings settings = sheetSettings(Integrator::Path, 1, 1);
    PreparedScene plain = prepareScene(furnaceSphere(translucent(1.0f, 0.5f, 0.0f), 1.0f));
    EXPECT_FALSE(hasDefine(WavefrontRenderer(gpuContext(), plain, settings, compiler)
                               .shaderDefines(),
                           "WF_HAS_DIFFUSE_TRANSMISSION"));
    PreparedScene on = prepareScene(furnaceSphere(translucent(1.0f, 0.5f, 0.5f), 1.0f));
    EXPECT_TRUE(hasDefine(WavefrontRenderer(gpuContext(), on, settings, compiler).shaderDefines(),
                          "WF_HAS_DIFFUSE_TRANSMISSION"));
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The switch compiles beside every other that touches the BSDF: textures, volume, the layered
// BSDF, anisotropy, path guiding, and the shade kinds' own BSDFs.
TEST(DiffuseTransmission, CompilesWithTheOtherMaterialSwitches) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    for (int bits = 0; bits < 16; ++bits)
        for (const char* pass : {"shade.comp", "megakernel.comp"}) {
            ShaderDefines defines = materialSwitchDefines(bits);
            defines.push_back({"WF_HAS_DIFFUSE_TRANSMISSION", "1"});
            if (bits == 15) {
                defines.push_back({"WF_HAS_ANISOTROPY", "1"});
                defines.push_back({"WF_HAS_TANGENTS", "0"});
            }
            ASSERT_GT(compiler.compile(pass, defines).spirv.size(), 5u) << pass << " " << bits;
        }
    for (const char* only : {"WF_BSDF_DELTA_ONLY", "WF_BSDF_DIFFUSE_ONLY"}) {
        ShaderDefines defines = {{"WF_WORKGROUP_SIZE", "64"}, {"WF_HAS_EMITTERS", "1"},
                                 {"WF_HAS_DIFFUSE_TRANSMISSION", "1"}, {only, "1"}};
        ASSERT_GT(compiler.compile("shade.comp", defines).spirv.size(), 5u) << only;
    }
}

} // namespace
} // namespace wf::test
