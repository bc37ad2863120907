// Shade kinds (src/passes/shade_kinds.h): which pass may shade a material, and the bins.
#include <gtest/gtest.h>

#include "passes/shade_kinds.h"
#include "scene/gltf/gltf_materials.h"

namespace wf {
namespace {

using gpu_types::Material;

Material lambert() { return gltf::defaultMaterial(); }

Material mirror() {
    Material m = lambert();
    m.metallic = 1.0f;
    m.roughness = 0.0f;
    return m;
}

Material glass() {
    Material m = lambert();
    m.transmission = 1.0f;
    m.roughness = 0.0f;
    m.specular = 1.0f;
    return m;
}

// KHR_materials_anisotropy stretches roughness 0 into a lobe with a density (alpha_t = s^2):
// no longer the specular kind's Dirac-only BSDF.
TEST(ShadeKinds, AnisotropicSmoothSurfacesAreGeneral) {
    for (Material m : {mirror(), glass()}) {
        m.anisotropyStrength = 0.3f;
        EXPECT_EQ(shadeKind(m), ShadeKind::General);
    }
}

// KHR_materials_diffuse_transmission sends Lambert light through the surface, which the
// diffuse kind's same-side Lambert BSDF cannot; the clear glass keeps no diffuse base to split.
TEST(ShadeKinds, DiffuseTransmissionIsGeneral) {
    Material m = lambert();
    m.diffuseTransmission = 0.5f;
    EXPECT_EQ(shadeKind(m), ShadeKind::General);
    Material g = glass();
    g.diffuseTransmission = 0.5f;
    EXPECT_EQ(shadeKind(g), ShadeKind::Specular);
}

TEST(ShadeKinds, MaterialsGetTheKindWhoseBsdfIsExactForThem) {
    EXPECT_EQ(shadeKind(lambert()), ShadeKind::Diffuse);
    EXPECT_EQ(shadeKind(mirror()), ShadeKind::Specular);
    EXPECT_EQ(shadeKind(glass()), ShadeKind::Specular);
    Material plastic = lambert();
    plastic.specular = 1.0f;
    EXPECT_EQ(shadeKind(plastic), ShadeKind::General);
    Material rough = mirror();
    rough.roughness = 0.3f;
    EXPECT_EQ(shadeKind(rough), ShadeKind::General);
    // A texture may lower metallic or transmission below 1, and so add a diffuse lobe.
    Material texturedMetal = mirror();
    texturedMetal.metallicRoughnessTexture = 0;
    EXPECT_EQ(shadeKind(texturedMetal), ShadeKind::General);
    Material texturedGlass = glass();
    texturedGlass.transmissionTexture = 0;
    EXPECT_EQ(shadeKind(texturedGlass), ShadeKind::General);
    // A roughness texture cannot raise roughness 0.
    Material texturedMirror = mirror();
    texturedMirror.metallic = 1.0f;
    texturedMirror.baseColorTexture = 0;
    EXPECT_EQ(shadeKind(texturedMirror), ShadeKind::Specular);
    // Layers need the layered BSDF.
    Material coated = lambert();
    coated.clearcoat = 1.0f;
    EXPECT_EQ(shadeKind(coated), ShadeKind::General);
    Material sheen = mirror();
    sheen.sheenColor = glm::vec3(0.5f);
    EXPECT_EQ(shadeKind(sheen), ShadeKind::General);
}

TEST(ShadeKinds, OneKindGetsNoBinsAndEachKindPresentABin) {
    EXPECT_EQ(shadeKindsFor(shadeKindsPresent({lambert(), lambert()})), 0u);
    EXPECT_EQ(shadeKindsFor(shadeKindsPresent({mirror(), glass()})), 0u);
    const uint32_t kinds = shadeKindsFor(shadeKindsPresent({lambert(), glass()}));
    EXPECT_EQ(kinds, 3u);
    EXPECT_EQ(shadeBinOf(kinds, ShadeKind::Diffuse), 0u);
    EXPECT_EQ(shadeBinOf(kinds, ShadeKind::Specular), 1u);
    EXPECT_EQ(lightHitBin(kinds), 1u);
    const uint32_t all = shadeKindsFor(7u);
    EXPECT_EQ(shadeBinOf(all, ShadeKind::General), 2u);
    const uint32_t noMirrors = shadeKindsFor(1u | 4u);
    EXPECT_EQ(shadeBinOf(noMirrors, ShadeKind::General), 1u);
    EXPECT_EQ(lightHitBin(noMirrors), 0u);
}

TEST(ShadeKinds, AutoSplitsOnlyScenesWithoutTheGeneralKind) {
    const uint32_t diffuseAndGlass = shadeKindsPresent({lambert(), glass()});
    const uint32_t withGeneral = 7u;
    EXPECT_EQ(shadeKindsFor(diffuseAndGlass, ShadeSplit::Auto), 3u);
    EXPECT_EQ(shadeKindsFor(withGeneral, ShadeSplit::Auto), 0u);
    EXPECT_EQ(shadeKindsFor(withGeneral, ShadeSplit::On), 7u);
    EXPECT_EQ(shadeKindsFor(diffuseAndGlass, ShadeSplit::Off), 0u);
    EXPECT_EQ(shadeKindsFor(shadeKindsPresent({lambert()}), ShadeSplit::On), 0u);
}

} // namespace
} // namespace wf
