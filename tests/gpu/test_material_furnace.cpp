// BSDF white furnace on the GPU: an object under a uniform environment of radiance E can never
// look brighter than E if its BSDF conserves energy, and a lossless one (white Lambert, clear
// glass) looks exactly E: it disappears.
#include <gtest/gtest.h>

#include "analytic_scenes.h"
#include "gpu_test_util.h"

namespace wf::test {
namespace {

Material makeMaterial(float metallic, float roughness, float transmission, float specular,
                      float base = 1.0f) {
    Material m{};
    m.baseColor = glm::vec4(base, base, base, 1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.ior = 1.5f;
    m.transmission = transmission;
    m.specular = specular;
    m.specularColor = glm::vec3(1.0f);
    return m;
}

// A KHR_materials_iridescence film (WF_HAS_IRIDESCENCE) over the material.
Material iridescent(Material m) {
    m.iridescence = 1.0f;
    m.iridescenceIor = 1.8f;
    m.iridescenceThicknessMinimum = 100.0f;
    m.iridescenceThicknessMaximum = 400.0f;
    m.iridescenceTexture = m.iridescenceThicknessTexture = WF_NO_TEXTURE;
    return m;
}

MeanAndError furnace(const Material& material, LightSampling sampling) {
    RenderSettings settings;
    settings.width = 24;
    settings.height = 24;
    settings.samplesPerPixel = 64;
    settings.maxDepth = 64;
    settings.lightSampling = sampling;
    settings.seed = 77;
    RenderResult result = renderScene(furnaceSphere(material, 1.0f), settings);
    EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
    return imageMean(result.rgb);
}

struct Case {
    const char* name;
    Material material;
    bool lossless; // expected to reflect everything: image == E
};

TEST(MaterialFurnace, NoMaterialCreatesEnergyAndLosslessOnesVanish) {
    const Case cases[] = {
        {"white Lambert", makeMaterial(0, 1, 0, 0), true},
        {"clear smooth glass", makeMaterial(0, 0, 1, 1), true},
        {"rough glass 0.3", makeMaterial(0, 0.3f, 1, 1), false},
        {"white dielectric 0.5", makeMaterial(0, 0.5f, 0, 1), false},
        {"smooth white dielectric", makeMaterial(0, 0, 0, 1), false},
        {"rough metal 0.6", makeMaterial(1, 0.6f, 0, 1), false},
        {"mirror", makeMaterial(1, 0, 0, 1), true},
        {"half metal 0.3", makeMaterial(0.5f, 0.3f, 0, 1), false},
        {"iridescent dielectric 0.3", iridescent(makeMaterial(0, 0.3f, 0, 1)), false},
        {"iridescent metal 0.4", iridescent(makeMaterial(1, 0.4f, 0, 1)), false},
        {"iridescent rough glass", iridescent(makeMaterial(0, 0.3f, 1, 1)), false},
    };
    for (const Case& c : cases) {
        for (LightSampling sampling : {LightSampling::Bsdf, LightSampling::Mis}) {
            MeanAndError m = furnace(c.material, sampling);
            const double bound = 1.0 + 4.0 * m.standardError + 2e-3;
            EXPECT_LE(m.mean, bound) << c.name << " creates energy ("
                                     << lightSamplingName(sampling) << ")";
            if (c.lossless)
                EXPECT_NEAR(m.mean, 1.0, 4.0 * m.standardError + 2e-3)
                    << c.name << " should vanish (" << lightSamplingName(sampling) << ")";
            std::printf("furnace %-26s %-4s %.4f +- %.4f\n", c.name, lightSamplingName(sampling),
                        m.mean, m.standardError);
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
