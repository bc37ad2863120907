// KHR_materials_dispersion on the GPU (lavapipe, validation on): white light through dispersive
// glass in the white furnace keeps the image's mean per channel (the wavelength weights
// average to white), with one wavelength per path and with hero wavelengths (--spectral), in
// the wavefront and the megakernel (the same samples, the same image); hero and single
// wavelengths agree per region on the prism, smooth and rough (both unbiased), hero is
// reproducible bit for bit and compiles in only where something disperses;
// scenes/prism.gltf casts a rainbow (red and blue land apart, far beyond the noise) while the
// same prism without dispersion is grey to the bit; dispersion 0 renders bit for bit as the
// file without the extension and compiles none of it; light subpaths refuse dispersive scenes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "analytic_scenes.h"
#include "errors.h"
#include "gpu_test_util.h"
#include "mini_gltf.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

Material glass(float dispersion, float roughness) {
    Material m{};
    m.baseColor = glm::vec4(1.0f);
    m.roughness = roughness;
    m.ior = 1.5f;
    m.transmission = 1.0f;
    m.specular = 1.0f;
    m.specularColor = glm::vec3(1.0f);
    m.dispersion = dispersion;
    m.baseColorTexture = m.metallicRoughnessTexture = m.normalTexture = m.emissiveTexture =
        m.transmissionTexture = m.specularTexture = m.specularColorTexture = WF_NO_TEXTURE;
    m.iridescenceTexture = m.iridescenceThicknessTexture = m.clearcoatTexture =
        m.clearcoatRoughnessTexture = m.clearcoatNormalTexture = m.sheenColorTexture =
            m.sheenRoughnessTexture = m.thicknessTexture = m.anisotropyTexture =
                m.diffuseTransmissionTexture = m.diffuseTransmissionColorTexture = WF_NO_TEXTURE;
    return m;
}

// Per channel: the pixels' mean and its standard error (pixels are independent estimates).
struct ChannelMeans {
    glm::dvec3 mean{0.0}, error{0.0};
};

ChannelMeans channelMeans(const std::vector<float>& rgb) {
    const size_t n = rgb.size() / 3;
    ChannelMeans m;
    glm::dvec3 sum2(0.0);
    for (size_t i = 0; i < n; ++i)
        for (int c = 0; c < 3; ++c) {
            m.mean[c] += rgb[3 * i + c];
            sum2[c] += double(rgb[3 * i + c]) * rgb[3 * i + c];
        }
    m.mean /= double(n);
    for (int c = 0; c < 3; ++c)
        m.error[c] = std::sqrt(std::max(sum2[c] / n - m.mean[c] * m.mean[c], 0.0) / (n - 1));
    return m;
}

TEST(Dispersion, WhiteFurnaceKeepsTheMeanPerChannel) {
    for (SpectralSampling spectral : {SpectralSampling::Single, SpectralSampling::Hero}) {
        for (float roughness : {0.0f, 0.3f}) {
            RenderSettings settings;
            settings.spectral = spectral;
            settings.width = settings.height = 24;
            settings.samplesPerPixel = 64;
            settings.maxDepth = 64;
            settings.seed = 17;
            const RenderResult plain = renderScene(furnaceSphere(glass(0.0f, roughness), 1.0f),
                                                   settings);
            const ChannelMeans p = channelMeans(plain.rgb);
            std::vector<float> wavefront;
            for (bool megakernel : {false, true}) {
                settings.megakernel = megakernel;
                const RenderResult r =
                    renderScene(furnaceSphere(glass(2.0f, roughness), 1.0f), settings);
                EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
                // The megakernel traces the same samples, wavelengths included: the same image
                // to float rounding.
                if (!megakernel)
                    wavefront = r.rgb;
                size_t differing = 0;
                for (size_t i = 0; i < r.rgb.size(); ++i)
                    differing +=
                        std::abs(r.rgb[i] - wavefront[i]) > 1e-4f * (1.0f + wavefront[i]);
                EXPECT_EQ(differing, 0u);
                const ChannelMeans d = channelMeans(r.rgb);
                std::printf("dispersion furnace, %s, roughness %.1f, %s: (%.4f %.4f %.4f) +- "
                            "(%.4f %.4f %.4f), without (%.4f %.4f %.4f)\n",
                            spectralSamplingName(spectral), roughness,
                            megakernel ? "megakernel" : "wavefront", d.mean.x, d.mean.y,
                            d.mean.z, d.error.x, d.error.y, d.error.z, p.mean.x, p.mean.y,
                            p.mean.z);
                for (int c = 0; c < 3; ++c) {
                    EXPECT_NEAR(d.mean[c], p.mean[c],
                                4.0 * std::hypot(d.error[c], p.error[c]) + 2e-3)
                        << "channel " << c;
                    EXPECT_GT(d.error[c], 0.0); // the wavelengths' colour noise is there
                }
            }
            settings.megakernel = false;
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

std::string readText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

std::string writeText(const TempDir& dir, const std::string& name, const std::string& text) {
    const std::string path = dir.path() + "/" + name;
    std::ofstream(path) << text;
    return path;
}

RenderSettings prismSettings() {
    RenderSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.samplesPerPixel = 16;
    settings.maxDepth = 6;
    settings.seed = 3;
    return settings;
}

bool exactlyGrey(const std::vector<float>& rgb) {
    for (size_t i = 0; i < rgb.size(); i += 3)
        if (rgb[i] != rgb[i + 1] || rgb[i] != rgb[i + 2])
            return false;
    return true;
}

// The floor camera of PrismCastsARainbow: it sees the rainbow's light arrive.
void lookFromTheFloor(Scene& scene) {
    const glm::vec3 floorPoint(1.45f, 0.02f, 0.0f), exitFace(0.17f, 0.9f, 0.0f);
    scene.camera.position = floorPoint;
    scene.camera.forward = glm::normalize(exitFace - floorPoint);
    scene.camera.up = glm::vec3(-scene.camera.forward.y, scene.camera.forward.x, 0.0f);
    scene.camera.yfov = 0.5f;
    scene.camera.aspect = 1.5f;
}

// The prism's rainbow, seen from where it falls: a camera on the floor of scenes/prism.gltf,
// in the beam, looks back up at the prism's exit face, and so sees what that point of the
// floor receives (the caustic, reversed: every pixel's path is Dirac up to the strip light, so
// it converges quickly). Rows of blocks, top to bottom, are red minus blue far beyond their
// noise on one side and far below on the other (the spectrum); without dispersion every pixel
// is exactly grey.
TEST(Dispersion, PrismCastsARainbow) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/prism.gltf");
    lookFromTheFloor(scene);
    RenderSettings settings = prismSettings();
    settings.samplesPerPixel = 64;
    // Each block's red minus blue over independent renders, whose spread is its noise (the
    // pixels of a block differ by the spectrum itself).
    const uint32_t block = 8, w = settings.width, h = settings.height;
    const uint32_t columns = w / block, blocks = columns * (h / block);
    const int seeds = 6;
    std::vector<double> sum(blocks, 0.0), sum2(blocks, 0.0);
    for (int seed = 0; seed < seeds; ++seed) {
        settings.seed = 40 + seed;
        const RenderResult r = renderScene(scene, settings);
        EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
        EXPECT_FALSE(exactlyGrey(r.rgb));
        std::vector<double> mean(blocks, 0.0);
        for (uint32_t y = 0; y < h / block * block; ++y)
            for (uint32_t x = 0; x < columns * block; ++x) {
                const size_t i = 3 * (size_t(y) * w + x);
                mean[(y / block) * columns + x / block] +=
                    (r.rgb[i] - r.rgb[i + 2]) / double(block * block);
            }
        for (uint32_t b = 0; b < blocks; ++b) {
            sum[b] += mean[b];
            sum2[b] += mean[b] * mean[b];
        }
    }
    for (Material& m : scene.materials)
        m.dispersion = 0.0f;
    EXPECT_TRUE(exactlyGrey(renderScene(scene, settings).rgb));
    int redder = 0, bluer = 0;
    for (uint32_t b = 0; b < blocks; ++b) {
        const double mean = sum[b] / seeds;
        const double error =
            std::sqrt(std::max(sum2[b] / seeds - mean * mean, 0.0) / (seeds - 1));
        std::printf("block %u %u: %.4f +- %.4f\n", b % columns, b / columns, mean, error);
        redder += mean > 5.0 * error && mean > 0.0;
        bluer += mean < -5.0 * error && mean < 0.0;
    }
    std::printf("prism: %d blocks redder, %d bluer beyond 5 standard errors\n", redder, bluer);
    EXPECT_GE(redder, 1);
    EXPECT_GE(bluer, 1);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// Per block of 8 x 8 pixels and channel, the mean over independent seeds and its standard
// error (the spread of the seeds' block means).
struct BlockMeans {
    std::vector<glm::dvec3> mean, error;
};

BlockMeans blockMeans(const Scene& scene, RenderSettings settings, int seeds) {
    const uint32_t block = 8, columns = settings.width / block;
    const uint32_t blocks = columns * (settings.height / block);
    BlockMeans b{std::vector<glm::dvec3>(blocks, glm::dvec3(0.0)),
                 std::vector<glm::dvec3>(blocks, glm::dvec3(0.0))};
    std::vector<glm::dvec3> sum2(blocks, glm::dvec3(0.0));
    for (int seed = 0; seed < seeds; ++seed) {
        settings.seed = 100 + seed;
        const RenderResult r = renderScene(scene, settings);
        EXPECT_EQ(r.stats.nonFiniteSamples, 0u);
        std::vector<glm::dvec3> mean(blocks, glm::dvec3(0.0));
        for (uint32_t y = 0; y < blocks / columns * block; ++y)
            for (uint32_t x = 0; x < columns * block; ++x) {
                const size_t i = 3 * (size_t(y) * settings.width + x);
                mean[(y / block) * columns + x / block] +=
                    glm::dvec3(r.rgb[i], r.rgb[i + 1], r.rgb[i + 2]) / double(block * block);
            }
        for (uint32_t k = 0; k < blocks; ++k) {
            b.mean[k] += mean[k] / double(seeds);
            sum2[k] += mean[k] * mean[k];
        }
    }
    for (uint32_t k = 0; k < blocks; ++k)
        b.error[k] = glm::sqrt(glm::max(sum2[k] / double(seeds) - b.mean[k] * b.mean[k],
                                        glm::dvec3(0.0)) /
                               double(seeds - 1));
    return b;
}

// Hero wavelengths and one wavelength per path are both unbiased: every block of the image
// agrees within 5 standard errors, on the smooth prism (seen from the floor, where its rainbow
// arrives through Dirac refractions, and from its own camera: reflections) and on the rough
// one (spectral MIS at rough refraction, next-event estimation inside the glass).
TEST(Dispersion, HeroAndSingleAgreePerRegion) {
    struct Case {
        const char* file;
        bool fromTheFloor;
    };
    for (const Case& c : {Case{"prism.gltf", true}, Case{"prism.gltf", false},
                          Case{"prism_rough.gltf", true}, Case{"prism_rough.gltf", false}}) {
        // The rough prism's rainbow on the floor is where each lane's own ior shows: every
        // lane evaluated at the sampling lane's ior reads 10 standard errors off there.
        Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/" + c.file);
        if (c.fromTheFloor)
            lookFromTheFloor(scene);
        RenderSettings settings = prismSettings();
        settings.width = 32;
        settings.height = 24;
        settings.samplesPerPixel = 32;
        const BlockMeans single = blockMeans(scene, settings, 5);
        settings.spectral = SpectralSampling::Hero;
        const BlockMeans hero = blockMeans(scene, settings, 5);
        double worst = 0.0, hue = 0.0;
        for (size_t k = 0; k < single.mean.size(); ++k)
            for (int ch = 0; ch < 3; ++ch) {
                const double error = std::hypot(single.error[k][ch], hero.error[k][ch]);
                const double gap = std::abs(single.mean[k][ch] - hero.mean[k][ch]);
                worst = std::max(worst, gap / std::max(error, 1e-12));
                EXPECT_LE(gap, 5.0 * error + 1e-6)
                    << c.file << " block " << k << " channel " << ch << ": single "
                    << single.mean[k][ch] << " +- " << single.error[k][ch] << ", hero "
                    << hero.mean[k][ch] << " +- " << hero.error[k][ch];
                hue += std::abs(single.mean[k][ch] - single.mean[k][(ch + 1) % 3]);
            }
        std::printf("%s%s: hero and single agree within %.2f standard errors\n", c.file,
                    c.fromTheFloor ? " from the floor" : "", worst);
        EXPECT_GT(hue, 0.0); // coloured: the comparison sees the spectrum
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// --spectral hero: the same seed gives the same image bit for bit; it compiles in
// (WF_SPECTRAL_HERO) only where something disperses, and changes nothing elsewhere.
TEST(Dispersion, HeroIsReproducibleAndOnlyWhereItDisperses) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/prism_rough.gltf");
    RenderSettings settings = prismSettings();
    settings.width = 24;
    settings.height = 16;
    settings.spectral = SpectralSampling::Hero;
    const RenderResult a = renderScene(scene, settings);
    const RenderResult b = renderScene(scene, settings);
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_FALSE(exactlyGrey(a.rgb));
    ShaderCompiler compiler(defaultShaderDir(), "");
    for (bool disperses : {true, false}) {
        for (Material& m : scene.materials)
            m.dispersion = disperses ? m.dispersion : 0.0f;
        PreparedScene prepared = prepareScene(scene);
        for (SpectralSampling spectral : {SpectralSampling::Single, SpectralSampling::Hero}) {
            settings.spectral = spectral;
            EXPECT_EQ(hasDefine(WavefrontRenderer(gpuContext(), prepared, settings, compiler)
                                    .shaderDefines(),
                                "WF_SPECTRAL_HERO"),
                      disperses && spectral == SpectralSampling::Hero);
        }
    }
    settings.spectral = SpectralSampling::Single;
    const RenderResult single = renderScene(scene, settings);
    settings.spectral = SpectralSampling::Hero;
    EXPECT_EQ(renderScene(scene, settings).rgb, single.rgb);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// dispersion 0 is the file without the extension, bit for bit, and neither compiles it in.
TEST(Dispersion, ZeroIsTheFileWithoutTheExtension) {
    const std::string text = readText(std::string(WF_TEST_SCENE_DIR) + "/prism.gltf");
    const std::string zero =
        std::regex_replace(text, std::regex(R"("dispersion": [0-9.]+)"), R"("dispersion": 0)");
    const std::string without = std::regex_replace(
        text, std::regex(R"(,\s*"KHR_materials_dispersion"(\s*:\s*\{[^}]*\})?)"), "");
    ASSERT_NE(zero, text);
    ASSERT_EQ(without.find("KHR_materials_dispersion"), std::string::npos);
    TempDir dir;
    const RenderSettings settings = prismSettings();
    const RenderResult a = renderScene(loadGltf(writeText(dir, "zero.gltf", zero)), settings);
    const RenderResult b =
        renderScene(loadGltf(writeText(dir, "without.gltf", without)), settings);
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_TRUE(exactlyGrey(a.rgb));
    ShaderCompiler compiler(defaultShaderDir(), "");
    for (const std::string* file : {&zero, &without, &text}) {
        PreparedScene prepared = prepareScene(loadGltf(writeText(dir, "scene.gltf", *file)));
        EXPECT_EQ(hasDefine(WavefrontRenderer(gpuContext(), prepared, settings, compiler)
                                .shaderDefines(),
                            "WF_HAS_DISPERSION"),
                  file == &text);
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Dispersion, LightSubpathsRefuseIt) {
    const Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/prism.gltf");
    for (Integrator integrator : {Integrator::Light, Integrator::Bdpt, Integrator::Vcm}) {
        RenderSettings settings = prismSettings();
        settings.samplesPerPixel = 1;
        settings.integrator = integrator;
        EXPECT_THROW(renderScene(scene, settings), UsageError) << integratorName(integrator);
    }
}

// The switch compiles beside the others that touch the path's vertex: textures, volume, the
// layered BSDF, path guiding, motion blur (its own camera dimensions), and the shade kinds'
// Dirac-only BSDF.
TEST(Dispersion, CompilesWithTheOtherSwitches) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    for (int bits = 0; bits < 16; ++bits)
        for (const char* pass : {"shade.comp", "megakernel.comp", "raygen.comp"}) {
            ShaderDefines defines = materialSwitchDefines(bits);
            defines.push_back({"WF_MOTION", bits == 15 ? "1" : "0"});
            defines.push_back({"WF_HAS_DISPERSION", "1"});
            ASSERT_GT(compiler.compile(pass, defines).spirv.size(), 5u) << pass << " " << bits;
            defines.push_back({"WF_SPECTRAL_HERO", "1"});
            ASSERT_GT(compiler.compile(pass, defines).spirv.size(), 5u)
                << pass << " " << bits << " hero";
        }
    const ShaderDefines delta = {{"WF_WORKGROUP_SIZE", "64"}, {"WF_HAS_EMITTERS", "1"},
                                 {"WF_HAS_DISPERSION", "1"}, {"WF_BSDF_DELTA_ONLY", "1"}};
    ASSERT_GT(compiler.compile("shade.comp", delta).spirv.size(), 5u);
    ShaderDefines deltaHero = delta;
    deltaHero.push_back({"WF_SPECTRAL_HERO", "1"});
    ASSERT_GT(compiler.compile("shade.comp", deltaHero).spirv.size(), 5u);
}

} // namespace
} // namespace wf::test
