// --integrator light and bdpt (issue 46): each estimates what the path tracer does, region by
// region, on the laboratory's scenes, except where light tracing meets a Dirac surface seen
// directly (it leaves those pixels black: no light subpath can connect through them); white
// furnace; the same seed gives the same image bit for bit; no NaN; what they cannot do yet is
// refused. On the glass caustic the path tracer's own estimate is heavy-tailed (the caustic's
// paths are rare to it), so bdpt is held to light tracing there, which samples them well.
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <stb_image_write.h>

#include "errors.h"
#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "image/error_metrics.h"
#include "instanced_scene.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/lights/light_table.h"

namespace wf::test {
namespace {

constexpr uint32_t kSize = 32;
constexpr uint32_t kBlock = 8;

RenderSettings settingsFor(Integrator integrator, uint32_t spp, uint32_t seed) {
    RenderSettings settings;
    settings.width = kSize;
    settings.height = kSize;
    settings.samplesPerPixel = spp;
    settings.maxDepth = 6;
    settings.seed = seed;
    settings.sampler = SamplerKind::Independent; // seeds and samples independent alike
    settings.integrator = integrator;
    return settings;
}

// `integrator`'s renders over `seeds` seeds against a reference of `referenceIntegrator` with
// its variance, per kBlock x kBlock region within 5 standard errors. The renders' error comes
// from their spread over seeds, not from their pixels' variance: one light subpath splats into
// several pixels of a region, so the pixels' errors are correlated; 16 seeds give that spread
// 15 degrees of freedom. Regions holding a pixel that light tracing left exactly 0 (every
// render, or the reference) while the other side is not are skipped (a Dirac surface seen
// directly); at least `minRegions` must be checked. Only light tracing's renders are skipped
// so: bdpt and vcm see Dirac surfaces through their camera subpaths, and a dim pixel that a
// few of the reference's paths reached may stay 0 in all of theirs by chance.
void expectAgreement(Integrator integrator, const Scene& scene, uint32_t referenceSpp,
                     uint32_t spp, int seeds, int minRegions, const std::string& what,
                     Integrator referenceIntegrator = Integrator::Path,
                     bool balance = false, uint32_t lightShare = 0) {
    RenderSettings reference = settingsFor(referenceIntegrator, referenceSpp, 9001);
    reference.aov = true; // the variance layer
    RenderResult path = renderScene(scene, reference);
    std::vector<std::vector<float>> images;
    const std::string name = what + " (" + integratorName(integrator) + ")";
    for (int seed = 0; seed < seeds; ++seed) {
        RenderSettings settings = settingsFor(integrator, spp, 100 + seed);
        settings.bdptBalance = balance;
        settings.lightShare = lightShare;
        RenderResult result = renderScene(scene, settings);
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u) << name;
        for (float v : result.rgb)
            ASSERT_TRUE(std::isfinite(v)) << name;
        images.push_back(std::move(result.rgb));
    }
    const uint32_t regionsPerRow = kSize / kBlock;
    std::vector<bool> skip(regionsPerRow * regionsPerRow, false);
    for (uint32_t i = 0; i < kSize * kSize; ++i) {
        const bool referenceBlack = path.rgb[3 * i] + path.rgb[3 * i + 1] + path.rgb[3 * i + 2] == 0.0f;
        bool allBlack = true;
        for (const auto& image : images)
            allBlack = allBlack && image[3 * i] + image[3 * i + 1] + image[3 * i + 2] == 0.0f;
        // Light tracing as the reference leaves the Dirac surfaces black instead.
        const bool lightReference = referenceIntegrator == Integrator::Light;
        const bool lightRender = integrator == Integrator::Light;
        if (lightReference ? referenceBlack && !allBlack
                           : lightRender && allBlack && !referenceBlack)
            skip[(i / kSize / kBlock) * regionsPerRow + (i % kSize) / kBlock] = true;
    }
    const int checked = expectRegionsUnbiased(images, path.rgb, path.aov.variance, kSize, kSize,
                                              kBlock, name, &skip);
    EXPECT_GE(checked, minRegions) << name;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

class Bidirectional : public ::testing::TestWithParam<Integrator> {};

Scene laboratoryScene(const char* name) {
    return loadGltf(std::string(WF_TEST_SCENE_DIR) + "/" + name + ".gltf");
}

TEST_P(Bidirectional, AgreesWithPathOnTheCornellBox) {
    expectAgreement(GetParam(), laboratoryScene("cornell_box"), 1024, 64, 16, 16, "cornell");
}

TEST_P(Bidirectional, AgreesWithPathOnVeachsPlates) {
    // Glossy plates seen directly: light tracing's failure case (splats land on few pixels),
    // still unbiased.
    expectAgreement(GetParam(), laboratoryScene("veach_mis"), 1024,
                    GetParam() == Integrator::Light ? 512 : 64, 16, 8, "veach");
}

TEST(LightTracing, AgreesWithPathOnTheGlassCausticAwayFromTheGlass) {
    // The caustic on the floor is light tracing's strength; the sphere seen directly stays
    // black, and the regions it covers are skipped (at most half of them).
    expectAgreement(Integrator::Light, laboratoryScene("glass_caustic"), 2048, 64, 16, 8,
                    "caustic");
}

TEST(Bdpt, AgreesWithLightTracingOnTheGlassCaustic) {
    // Light tracing as the reference (see the top of the file), so only the regions it
    // reaches: bdpt itself sees the glass through the camera's Dirac bounces.
    expectAgreement(Integrator::Bdpt, laboratoryScene("glass_caustic"), 1024, 64, 16, 8,
                    "caustic", Integrator::Light);
}

TEST_P(Bidirectional, AgreesWithPathThroughRoughGlass) {
    // Rough glass seen directly connects to the camera from either side of the interface,
    // where importance must not take the 1 / eta^2 that radiance takes (adjoint_bsdf.h).
    Scene scene = laboratoryScene("glass_caustic");
    for (Material& material : scene.materials)
        if (material.transmission > 0.0f)
            material.roughness = 0.3f;
    expectAgreement(GetParam(), scene, 1024, 64, 16, 12, "rough glass");
}

TEST_P(Bidirectional, AgreesWithPathUnderSphereLights) {
    expectAgreement(GetParam(), laboratoryScene("sphere_near_floor"), 1024, 64, 16, 8, "sphere");
}

TEST_P(Bidirectional, AgreesWithPathOnInstancedNormalMappedMeshes) {
    // Two-level BVH, textures and shading normals that differ from the geometric ones: the
    // adjoint BSDF's correction (bidir/adjoint_bsdf.h) is what keeps this unbiased.
    TempDir dir;
    expectAgreement(GetParam(), loadGltf(writeNormalMappedInstancedScene(dir)), 1024, 64, 16,
                    16, "instances");
}

TEST_P(Bidirectional, AgreesWithPathThroughTexturedAlphaCutOuts) {
    // The instanced blobs textured by an RGBA image whose alpha (filtered across its texels)
    // cuts out about half of each blob (alphaMode MASK): light subpaths, their splats' and
    // connections' shadow rays, and merges must pass the cut-outs as camera rays do.
    TempDir dir;
    const std::vector<uint8_t> texels = {230, 60, 40, 255, 40, 200, 90, 0,
                                         40, 90, 220, 0, 240, 220, 60, 255};
    ASSERT_TRUE(stbi_write_png(dir.file("cutout.png").c_str(), 2, 2, 4, texels.data(), 8));
    const std::string file = writeInstancedScene(
        dir, R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0},"metallicFactor":0,
        "roughnessFactor":0.5},"alphaMode":"MASK","doubleSided":true})", "cutout.png");
    const Scene scene = loadGltf(file);
    ASSERT_EQ(scene.materials[0].flags & WF_MATERIAL_ALPHA_MASK, WF_MATERIAL_ALPHA_MASK);
    expectAgreement(GetParam(), scene, 1024, 64, 16, 16, "textured alpha cut-outs");
}

TEST_P(Bidirectional, AgreesWithPathOnAnisotropicMeshes) {
    // KHR_materials_anisotropy on the same normal-mapped (some mirrored) instances: the BSDF
    // turns with its frame's x axis, the material's direction, which light vertices must build
    // as the path tracer does (wave/shading_frame.glsl); a frame turned about the normal is
    // biased here.
    TempDir dir;
    Scene scene = loadGltf(writeNormalMappedInstancedScene(dir));
    for (Material& m : scene.materials)
        if (m.normalTexture != WF_NO_TEXTURE) {
            m.metallic = 1.0f;
            m.anisotropyStrength = 0.9f;
            m.anisotropyRotation = glm::vec2(std::cos(1.1f), std::sin(1.1f));
        }
    expectAgreement(GetParam(), scene, 1024, 64, 16, 16, "anisotropic instances");
}

TEST_P(Bidirectional, AgreesWithPathThroughAThinLens) {
    Scene scene = laboratoryScene("cornell_box");
    scene.camera.aperture = 0.4f;
    scene.camera.focusDistance =
        glm::dot(sceneBounds(scene).center - scene.camera.position, scene.camera.forward);
    expectAgreement(GetParam(), scene, 1024, 64, 16, 16, "thin lens");
}

TEST_P(Bidirectional, WhiteFurnaceSumsTheSeriesToMaxDepth) {
    // Camera inside a closed box whose walls emit E and reflect a: a path of at most D
    // segments collects E (1 - a^D) / (1 - a); the camera rays find the first term, light
    // subpaths the rest.
    const float albedo = 0.5f, emission = 0.5f;
    for (uint32_t depth : {1u, 2u, 4u, 40u}) {
        RenderSettings settings = settingsFor(GetParam(), 64, 5);
        settings.maxDepth = depth;
        RenderResult result = renderScene(furnaceBox(albedo, emission), settings);
        const double expected = emission * (1.0 - std::pow(albedo, depth)) / (1.0 - albedo);
        MeanAndError measured = imageMean(result.rgb);
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
        EXPECT_NEAR(measured.mean, expected, 4.0 * measured.standardError + 1e-4 * expected)
            << "max depth " << depth;
        EXPECT_NEAR(measured.mean, expected, 0.01 * expected) << "max depth " << depth;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST_P(Bidirectional, SameSeedSameImageBitForBit) {
    // The light film adds splats as integers, which commute: no order of arrival shows.
    const Scene scene = laboratoryScene("cornell_box");
    RenderSettings settings = settingsFor(GetParam(), 16, 3);
    settings.sampler = SamplerKind::Sobol;
    const std::vector<float> first = renderScene(scene, settings).rgb;
    settings.maxPathsPerWave = 3 * kSize * kSize; // other wave sizes: whole samples still
    const std::vector<float> second = renderScene(scene, settings).rgb;
    ASSERT_EQ(first.size(), second.size());
    EXPECT_EQ(std::memcmp(first.data(), second.data(), first.size() * sizeof(float)), 0);
    settings.seed = 4;
    EXPECT_NE(renderScene(scene, settings).rgb, first);
}

TEST_P(Bidirectional, RefusesWhatItCannotTrace) {
    const Scene cornell = laboratoryScene("cornell_box");
    RenderSettings settings = settingsFor(GetParam(), 4, 1);
    settings.megakernel = true;
    EXPECT_THROW(renderScene(cornell, settings), UsageError);
    settings = settingsFor(GetParam(), 4, 1);
    settings.pixelList = true;
    EXPECT_THROW(renderScene(cornell, settings), UsageError);
    settings = settingsFor(GetParam(), 4, 1);
    settings.guiding = true;
    EXPECT_THROW(renderScene(cornell, settings), UsageError);
    Scene orthographic = cornell;
    orthographic.camera.orthoHalfHeight = 1.0f;
    EXPECT_THROW(renderScene(orthographic, settingsFor(GetParam(), 4, 1)), UsageError);
}

TEST_P(Bidirectional, ErrorEstimateStaysCalibratedWithSplats) {
    // A pixel's samples are its camera values plus the splats of their sample index's light
    // subpaths into it (accumulate.comp), so the film's moments (independent samples) and the
    // replicates (a correlated sampler) measure the error the splats carry too.
    const Scene scene = laboratoryScene("cornell_box");
    RenderSettings referenceSettings = settingsFor(Integrator::Path, 4096, 4242);
    const std::vector<float> reference = renderScene(scene, referenceSettings).rgb;
    int reliable = 0;
    for (SamplerKind sampler : {SamplerKind::Independent, SamplerKind::Sobol})
        for (uint32_t seed = 1; seed <= 3; ++seed) {
            RenderSettings settings = settingsFor(GetParam(), 64, seed);
            settings.sampler = sampler;
            settings.errorReplicates = 2; // the independent sampler ignores it
            const RenderResult result = renderScene(scene, settings);
            const double measured = imageError(result.rgb, reference).relMse;
            const ErrorEstimate& e = result.estimate;
            EXPECT_FALSE(e.upperBound);
            if (!e.reliable)
                continue;
            ++reliable;
            EXPECT_GE(e.relMse / measured, 0.7) << samplerName(sampler) << " seed " << seed;
            EXPECT_LE(e.relMse / measured, 1.4) << samplerName(sampler) << " seed " << seed;
        }
    EXPECT_GE(reliable, 4);
}

TEST_P(Bidirectional, WhiteFurnaceSphereUnderAnEnvironment) {
    // Light subpaths from the environment (its disk over the scene's bounds) onto a white
    // Lambertian sphere that fills the view: every pixel sees exactly the environment's L.
    Material white{};
    white.baseColor = glm::vec4(1.0f);
    white.roughness = 1.0f;
    white.ior = 1.5f;
    white.specularColor = glm::vec3(1.0f);
    RenderSettings settings = settingsFor(GetParam(), 64, 11);
    settings.maxDepth = 40;
    const RenderResult result = renderScene(furnaceSphere(white, 0.5f), settings);
    const MeanAndError measured = imageMean(result.rgb);
    EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
    EXPECT_NEAR(measured.mean, 0.5, 4.0 * measured.standardError + 1e-4);
    EXPECT_LT(measured.standardError, 0.02); // so that 4 of them still tell
}

TEST(Vcm, MergesCarryAFloorUnderAnEnvironment) {
    // Wide radii, so that merging takes most of the weight (eta = pi r^2 W H against a
    // connection's 1). Under a uniform environment the photons land on the floor with a
    // uniform density, and the floor is flat and far wider than the view and the radius, so
    // the merges are unbiased here at any radius: any error in their normalisation or weights
    // shows. (On curved or cornered surfaces merging is biased by O(r^2): a flat-faceted unit
    // sphere at r = 0.35 reads 5% dark.) Pixels share photons, so the error comes from the
    // spread of independent seeds' means.
    const float albedo = 0.5f;
    Scene scene = floorScene(albedo);
    scene.camera.yfov = 1.0f;
    scene.environment = rowEnvironment(1, 1, nullptr);
    scene.environment.rgb = {0.25f, 0.25f, 0.25f};
    const double expected = lambertRadiance(albedo, M_PI * 0.25);
    for (float radius : {0.01f, 0.05f, 0.2f}) { // 0.01: the default
        std::vector<double> means;
        for (uint32_t seed = 0; seed < 8; ++seed) {
            RenderSettings settings = settingsFor(Integrator::Vcm, 64, 20 + seed);
            settings.width = settings.height = 24;
            settings.maxDepth = 2;
            settings.vcmRadius = radius;
            const RenderResult result = renderScene(scene, settings);
            EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
            means.push_back(imageMean(result.rgb).mean);
        }
        double mean = 0.0, spread = 0.0;
        for (double m : means)
            mean += m / means.size();
        for (double m : means)
            spread += (m - mean) * (m - mean) / (means.size() - 1);
        const double standardError = std::sqrt(spread / means.size());
        EXPECT_NEAR(mean, expected, 4.0 * standardError) << radius;
        EXPECT_LT(standardError, 0.04 * expected) << radius; // so that 4 of them tell
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

TEST(Bdpt, BalanceHeuristicAgreesWithPath) {
    // --bdpt-heuristic balance: the same strategies, other weights, still summing to 1.
    expectAgreement(Integrator::Bdpt, laboratoryScene("cornell_box"), 1024, 64, 16, 16,
                    "cornell, balance", Integrator::Path, true);
}

TEST(LightShare, SharedOrNotTheIntegratorsAgreeWithPath) {
    // --light-share: light and vcm with 4 pixels to a light subpath (they default to 1), bdpt
    // with one per pixel (it defaults to 8, which the suite above checks). A splat not scaled
    // by the pixels per subpath, or MIS weights that count one subpath per pixel, fail it.
    struct Case {
        Integrator integrator;
        uint32_t share;
    };
    for (const Case c : {Case{Integrator::Light, 4}, Case{Integrator::Vcm, 4},
                         Case{Integrator::Bdpt, 1}})
        expectAgreement(c.integrator, laboratoryScene("cornell_box"), 1024, 64, 16, 16,
                        "cornell, light share " + std::to_string(c.share), Integrator::Path,
                        false, c.share);
}

TEST(Bdpt, FloorUnderEveryLightKind) {
    // Closed forms (analytic_scenes.h): a point, a directional light and two spots (one aimed
    // away), a sphere light and an environment over a Lambertian floor, at max depth 2, over
    // three seeds.
    const float albedo = 0.5f;
    Scene scene = floorScene(albedo);
    const float radius = 0.5f, height = 1.5f;
    scene.lights.push_back(sphereLight({-1.0f, height, 0.5f}, radius, glm::vec3(4.0f)));
    scene.environment = rowEnvironment(1, 1, nullptr);
    scene.environment.rgb = {0.25f, 0.25f, 0.25f};
    const double diracIrradiance = addDiracLights(scene);
    const glm::vec3 toSphere(-1.0f, height, 0.5f);
    const double sphereRadiance = 4.0 / (M_PI * radius * radius);
    const double sphereDistance = glm::length(toSphere);
    // A sphere wholly above the horizon: E = pi L (R / d)^2 cos(theta).
    const double irradiance =
        diracIrradiance +
        M_PI * sphereRadiance * radius * radius / (sphereDistance * sphereDistance) *
            (height / sphereDistance) +
        M_PI * 0.25;
    const double expected = lambertRadiance(albedo, irradiance);
    for (uint32_t seed = 0; seed < 3; ++seed) {
        RenderSettings settings = settingsFor(Integrator::Bdpt, 32, 1000 + seed);
        settings.width = settings.height = 24;
        settings.maxDepth = 2;
        const RenderResult result = renderScene(scene, settings);
        const MeanAndError m = imageMean(result.rgb);
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
        EXPECT_NEAR(m.mean, expected, 4.0 * m.standardError + 1e-4 * expected) << "seed " << seed;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Integrators, Bidirectional,
                         ::testing::Values(Integrator::Light, Integrator::Bdpt, Integrator::Vcm),
                         [](const ::testing::TestParamInfo<Integrator>& info) {
                             return std::string(integratorName(info.param));
                         });

} // namespace
} // namespace wf::test
