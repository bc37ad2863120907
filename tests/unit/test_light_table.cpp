// The emitter alias table: the probability each emitter is chosen, computed exactly from the
// table, equals its power share; zero-area and black triangles are never emitters.
#include <gtest/gtest.h>

#include "scene/lights/light_table.h"

namespace wf {
namespace {

// Exact probability of choosing each slot through the table, as lights.glsl does it.
std::vector<double> choiceProbabilities(const std::vector<Emitter>& table) {
    std::vector<double> p(table.size(), 0.0);
    const double slot = 1.0 / table.size();
    for (size_t i = 0; i < table.size(); ++i) {
        p[i] += slot * table[i].aliasProb;
        p[table[i].alias] += slot * (1.0 - table[i].aliasProb);
    }
    return p;
}

TEST(AliasTable, ChoiceProbabilitiesMatchWeights) {
    const std::vector<double> weights = {1.0, 0.0, 7.5, 0.25, 3.0, 3.0, 1e-6, 40.0};
    double total = 0.0;
    for (double w : weights)
        total += w;
    auto table = buildAliasTable(weights);
    ASSERT_EQ(table.size(), weights.size());
    auto p = choiceProbabilities(table);
    for (size_t i = 0; i < weights.size(); ++i) {
        EXPECT_NEAR(p[i], weights[i] / total, 1e-6) << "slot " << i;
        EXPECT_NEAR(table[i].pmf, weights[i] / total, 1e-6);
        EXPECT_LT(table[i].alias, weights.size());
    }
}

TEST(AliasTable, EmptyOrZeroWeightsGiveNoTable) {
    EXPECT_TRUE(buildAliasTable({}).empty());
    EXPECT_TRUE(buildAliasTable({0.0, 0.0}).empty());
}

TEST(LightTable, OnlyEmissiveTrianglesOfPositiveAreaByPower) {
    std::vector<Material> materials(3);
    materials[0].emission = glm::vec3(0.0f);               // not emissive
    materials[1].emission = glm::vec3(2.0f, 2.0f, 2.0f);   // one-sided
    materials[2].emission = glm::vec3(1.0f, 1.0f, 1.0f);
    materials[2].flags = WF_MATERIAL_DOUBLE_SIDED;          // twice the power per area
    auto tri = [](glm::vec3 a, glm::vec3 b, glm::vec3 c, uint32_t m) {
        return Triangle{a, m, b, 0, c, 0};
    };
    std::vector<Triangle> triangles = {
        tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0),
        tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1), // area 0.5
        tri({0, 0, 0}, {2, 0, 0}, {0, 1, 0}, 2), // area 1
        tri({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, 1), // collinear: zero area
    };
    std::vector<PunctualLight> lights;
    LightTable table = buildLightTable(triangles, materials, lights, {}, sceneBounds(triangles, lights));
    ASSERT_EQ(table.emitters.size(), 2u);
    EXPECT_EQ(triangles[0].emitter, WF_NO_EMITTER);
    EXPECT_EQ(triangles[3].emitter, WF_NO_EMITTER);
    ASSERT_NE(triangles[1].emitter, WF_NO_EMITTER);
    ASSERT_NE(triangles[2].emitter, WF_NO_EMITTER);
    // Powers: 2 * 0.5 * pi * 1 = pi and 1 * 1 * pi * 2 = 2 pi.
    EXPECT_NEAR(table.emitters[triangles[1].emitter].pmf, 1.0 / 3.0, 1e-6);
    EXPECT_NEAR(table.emitters[triangles[2].emitter].pmf, 2.0 / 3.0, 1e-6);
    EXPECT_EQ(table.emitters[triangles[1].emitter].source, WF_EMITTER_TRIANGLE | 1u);
    EXPECT_NEAR(table.totalPower, 3.0 * M_PI, 1e-9);
}

// An emissive texture, white on its left half and black on its right (linear, repeat): the
// triangle over the white half weighs as its factor says, the one over the black half next to
// nothing but not nothing (it could still shine somewhere its samples missed).
TEST(LightTable, EmissiveTextureMeanWeighsTriangles) {
    std::vector<Material> materials(1);
    materials[0].emission = glm::vec3(3.0f);
    materials[0].emissiveTexture = 0;
    auto tri = [](glm::vec3 a, glm::vec3 b, glm::vec3 c) { return Triangle{a, 0, b, 0, c, 0}; };
    std::vector<Triangle> triangles = {tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0}),
                                       tri({0, 0, 0}, {1, 0, 0}, {0, 1, 0})};
    SurfaceData surface;
    surface.textureRefs.resize(1);
    surface.textureRefs[0].uRow = glm::vec3(1, 0, 0);
    surface.textureRefs[0].vRow = glm::vec3(0, 1, 0);
    surface.textureRefs[0].width = 2;
    surface.textureRefs[0].height = 1;
    surface.refImage = {0};
    surface.images.push_back({2, 1, {0xffffffffu, 0xff000000u}, "half white"});
    surface.uv0 = {{{0.05f, 0.1f}, {0.45f, 0.1f}, {0.05f, 0.9f}},  // left half
                   {{0.55f, 0.1f}, {0.95f, 0.1f}, {0.55f, 0.9f}}}; // right half
    std::vector<PunctualLight> lights;
    LightTable table = buildLightTable(triangles, materials, lights, {},
                                       sceneBounds(triangles, lights), surface);
    ASSERT_EQ(table.emitters.size(), 2u);
    const double white = table.emitters[triangles[0].emitter].pmf;
    const double black = table.emitters[triangles[1].emitter].pmf;
    EXPECT_NEAR(white / black, 1024.0, 1.0);
    EXPECT_NEAR(table.totalPower, (3.0 + 3.0 / 1024.0) * 0.5 * M_PI, 1e-6);
}

} // namespace
} // namespace wf
