// The material extensions' textures as the loader reads them (issue 48): clearcoat, coat
// roughness and coat normal, sheen colour and roughness, thickness, transmission and the
// specular pair, each with its own KHR_texture_transform and UV set, with no warning; and
// KHR_texture_basisu's PNG fallback read silently, one warning where there is none.
#include <gtest/gtest.h>

#include <string>

#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_materials.h"

namespace wf {
namespace {

struct Loaded {
    Scene scene;
    std::string err;
};

Loaded load(const std::string& name) {
    ::testing::internal::CaptureStderr();
    Loaded out{loadGltf(std::string(WF_TEST_CORPUS_DIR) + "/valid/" + name), ""};
    out.err = ::testing::internal::GetCapturedStderr();
    return out;
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1))
        ++n;
    return n;
}

// make_corpus.py gives the k-th texture a transform of scale (k, 1), so uRow.x tells which
// textureInfo reached which field.
TEST(GltfLayerTextures, EveryTextureWithItsTransformReachesTheMaterial) {
    const Loaded loaded = load("material_layer_textures.gltf");
    EXPECT_EQ(loaded.err, "") << "no texture of these extensions is ignored any more";
    const Scene& scene = loaded.scene;
    ASSERT_EQ(scene.materials.size(), 1u);
    const Material& m = scene.materials[0];
    struct Field {
        const char* name;
        uint32_t ref;
        float scale;
        bool srgb;
        bool texCoord1;
    };
    const Field fields[] = {
        {"clearcoatTexture", m.clearcoatTexture, 2, false, false},
        {"clearcoatRoughnessTexture", m.clearcoatRoughnessTexture, 3, false, true},
        {"clearcoatNormalTexture", m.clearcoatNormalTexture, 4, false, false},
        {"sheenColorTexture", m.sheenColorTexture, 5, true, false},
        {"sheenRoughnessTexture", m.sheenRoughnessTexture, 6, false, false},
        {"transmissionTexture", m.transmissionTexture, 7, false, false},
        {"thicknessTexture", m.thicknessTexture, 8, false, false},
        {"specularTexture", m.specularTexture, 9, false, false},
        {"specularColorTexture", m.specularColorTexture, 10, true, false},
    };
    for (const Field& f : fields) {
        ASSERT_LT(f.ref, scene.surface.textureRefs.size()) << f.name;
        const TextureRef& ref = scene.surface.textureRefs[f.ref];
        EXPECT_FLOAT_EQ(ref.uRow.x, f.scale) << f.name;
        EXPECT_FLOAT_EQ(ref.vRow.y, 1.0f) << f.name;
        EXPECT_EQ((ref.flags & WF_TEXTURE_SRGB) != 0, f.srgb) << f.name;
        EXPECT_EQ((ref.flags & WF_TEXTURE_TEXCOORD1) != 0, f.texCoord1) << f.name;
    }
    EXPECT_FLOAT_EQ(m.clearcoatNormalScale, 0.5f);
    EXPECT_FLOAT_EQ(m.clearcoat, 0.8f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.25f);
    EXPECT_FLOAT_EQ(m.thickness, 0.2f);
    EXPECT_EQ(scene.surface.uv1.size(), scene.triangles.size());
    EXPECT_EQ(scene.surface.tangents.size(), scene.triangles.size());

    // Without the textures: none, and the coat normal map's scale is 1.
    const Material plain = load("material_extensions.gltf").scene.materials[0];
    for (uint32_t ref : {plain.clearcoatTexture, plain.clearcoatRoughnessTexture,
                         plain.clearcoatNormalTexture, plain.sheenColorTexture,
                         plain.sheenRoughnessTexture, plain.thicknessTexture})
        EXPECT_EQ(ref, WF_NO_TEXTURE);
    EXPECT_EQ(plain.clearcoatNormalScale, 1.0f);
}

// A coat normal map without a base one: the primitive still gets its tangent frames.
TEST(GltfLayerTextures, CoatNormalMapAloneGetsTangents) {
    const Loaded loaded = load("clearcoat_normal_map_only.gltf");
    EXPECT_EQ(loaded.err, "");
    const Material& m = loaded.scene.materials[0];
    EXPECT_EQ(m.normalTexture, WF_NO_TEXTURE);
    ASSERT_NE(m.clearcoatNormalTexture, WF_NO_TEXTURE);
    EXPECT_EQ(m.clearcoatNormalScale, 1.0f);
    EXPECT_EQ(loaded.scene.surface.tangents.size(), loaded.scene.triangles.size());
}

// KHR_texture_basisu with a PNG `source`: that is read, silently; the KTX2 image is not.
TEST(GltfLayerTextures, BasisuFallbackIsReadSilently) {
    const Loaded loaded = load("texture_basisu_fallback.gltf");
    EXPECT_EQ(loaded.err, "");
    const Scene& scene = loaded.scene;
    const Material& m = scene.materials[0];
    ASSERT_NE(m.baseColorTexture, WF_NO_TEXTURE);
    ASSERT_EQ(scene.surface.images.size(), 1u);
    const TextureImage& image = scene.surface.images[scene.surface.refImage[m.baseColorTexture]];
    EXPECT_EQ(image.width, 8u); // the PNG checker
    EXPECT_EQ(image.height, 8u);
}

// Without a fallback the textures are dropped, with one warning for the file (not one per
// texture, nor "ignoring glTF extension" besides).
TEST(GltfLayerTextures, BasisuWithoutFallbackWarnsOnce) {
    const Loaded loaded = load("texture_basisu_without_fallback.gltf");
    EXPECT_EQ(count(loaded.err, "warning"), 1u) << loaded.err;
    EXPECT_EQ(count(loaded.err, "KHR_texture_basisu"), 1u) << loaded.err;
    const Material& m = loaded.scene.materials[0];
    EXPECT_EQ(m.baseColorTexture, WF_NO_TEXTURE);
    EXPECT_EQ(m.emissiveTexture, WF_NO_TEXTURE);
    EXPECT_TRUE(loaded.scene.surface.images.empty());
}

} // namespace
} // namespace wf
