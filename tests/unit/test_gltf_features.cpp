// What the corpus files mean, beyond loading: sparse and quantized values, strip winding,
// normals and tangents in world space, texture references, lights and cameras.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/packing.hpp>

#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/gltf/gltf_primitives.h"

namespace wf {
namespace {

Scene load(const std::string& name) {
    return loadGltf(std::string(WF_TEST_CORPUS_DIR) + "/valid/" + name);
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-4f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

glm::vec3 decode(uint32_t packed) {
    return gpu_types::octDecode(glm::unpackSnorm2x16(packed));
}

TEST(GltfFeatures, OctahedralNormalsRoundTrip) {
    for (int i = 0; i < 1000; ++i) {
        const float z = 1.0f - 2.0f * (i + 0.5f) / 1000.0f, phi = 2.4f * i;
        const float r = std::sqrt(1.0f - z * z);
        const glm::vec3 n(r * std::cos(phi), r * std::sin(phi), z);
        EXPECT_GT(glm::dot(decode(gltf::octEncode(n)), n), 0.99999f);
    }
    expectNear(decode(gltf::octEncode({0, 0, -1})), {0, 0, -1});
}

TEST(GltfFeatures, SparseValuesReplaceDenseOnes) {
    Scene scene = load("sparse_positions.gltf");
    ASSERT_EQ(scene.triangles.size(), 2u);
    expectNear(scene.triangles[0].p2, {2, 2, 0}); // vertex 2 replaced by the sparse value
    Scene zeros = load("sparse_without_bufferview.gltf");
    expectNear(zeros.triangles[0].p0, {0, 0, 0});
    expectNear(zeros.triangles[0].p1, {1, 0, 0});
}

TEST(GltfFeatures, QuantizedAttributesAreDequantized) {
    Scene scene = load("quantized_short_normalized.gltf"); // node scale 2
    expectNear(scene.triangles[0].p1, {2, 0, 0});
    expectNear(scene.triangles[0].p2, {0, 2, 0});
    ASSERT_EQ(scene.surface.normals.size(), 1u);
    expectNear(decode(scene.surface.normals[0].n1), glm::normalize(glm::vec3(0, 1, 1)), 1e-3f);
    expectNear(load("quantized_ubyte.gltf").triangles[0].p1, {10, 0, 0});
}

TEST(GltfFeatures, StripsAndFansKeepCounterClockwiseFaces) {
    for (const char* name : {"triangle_strip.gltf", "triangle_fan_indexed.gltf"}) {
        for (const Triangle& t : load(name).triangles) {
            EXPECT_GT(glm::cross(t.p1 - t.p0, t.p2 - t.p0).z, 0.0f) << name;
        }
    }
}

TEST(GltfFeatures, TexturesKeepSamplerTransformAndColourSpace) {
    Scene scene = load("texture_transform_sampler.gltf");
    ASSERT_EQ(scene.surface.textureRefs.size(), 1u);
    const TextureRef& ref = scene.surface.textureRefs[0];
    EXPECT_EQ(ref.flags & 3u, WF_WRAP_MIRROR);
    EXPECT_EQ(ref.flags >> 2 & 3u, WF_WRAP_CLAMP);
    EXPECT_TRUE(ref.flags & WF_TEXTURE_SRGB);
    EXPECT_TRUE(ref.flags & WF_TEXTURE_NEAREST);
    // offset (0.5, 0), rotation 0.3, scale 2: u' = 2cos(.3) u + 2sin(.3) v + 0.5
    expectNear(ref.uRow, {2 * std::cos(0.3f), 2 * std::sin(0.3f), 0.5f});
    expectNear(ref.vRow, {-2 * std::sin(0.3f), 2 * std::cos(0.3f), 0.0f});
    EXPECT_EQ(scene.materials[0].baseColorTexture, 0u);
    const TextureImage& image = scene.surface.images[scene.surface.refImage[0]];
    EXPECT_EQ(image.width, 8u);
    EXPECT_EQ(image.rgba[0], 0xfff0f0f0u); // the checker's light square, opaque
    EXPECT_EQ(load("texture_jpeg_in_bufferview.glb").surface.images[0].width, 8u);
}

// EXT_texture_webp's source is taken over the core PNG one, from a data URI or a bufferView,
// and decoded exactly (lossless): 4x4 blocks of light grey and green.
TEST(GltfFeatures, WebpTexturesAreDecoded) {
    for (const char* name :
         {"texture_webp.gltf", "texture_webp_in_bufferview.glb", "texture_webp_only.gltf"}) {
        SCOPED_TRACE(name);
        Scene scene = load(name);
        ASSERT_EQ(scene.surface.images.size(), 1u);
        const TextureImage& image = scene.surface.images[scene.surface.refImage[0]];
        ASSERT_EQ(image.width, 8u);
        ASSERT_EQ(image.height, 8u);
        EXPECT_EQ(image.rgba[0], 0xfff0f0f0u);          // (0, 0): grey
        EXPECT_EQ(image.rgba[4], 0xff28c828u);          // (4, 0): green (40, 200, 40)
        EXPECT_EQ(image.rgba[4 * 8 + 4], 0xfff0f0f0u);  // (4, 4): grey
    }
}

// COLOR_0: float RGB and normalized u8 RGBA at the corners, opaque white where a primitive
// has none; the GPU reads them packed as unorm8 RGBA.
TEST(GltfFeatures, VertexColoursAtTheCorners) {
    Scene scene = load("vertex_colors.gltf");
    ASSERT_EQ(scene.surface.colors.size(), 6u);
    EXPECT_EQ(scene.surface.colors[0].c0, 0xff0000ffu); // vertex 0: red, alpha 1
    EXPECT_EQ(scene.surface.colors[0].c1, 0xff00ff00u); // vertex 1: green
    EXPECT_EQ(scene.surface.colors[2].c1, 0x8000ff00u); // u8 green with alpha 128
    for (size_t t : {4u, 5u})
        for (uint32_t c : {scene.surface.colors[t].c0, scene.surface.colors[t].c1,
                           scene.surface.colors[t].c2})
            EXPECT_EQ(c, 0xffffffffu);
    EXPECT_TRUE(load("triangle.gltf").surface.colors.empty()); // no COLOR_0, no array
}

// KHR_materials_unlit: the base colour becomes emission (factor and texture), and nothing
// scatters; alpha stays with the base colour.
TEST(GltfFeatures, UnlitMaterialsEmitTheirBaseColour) {
    const Material plain = load("unlit.gltf").materials[0];
    EXPECT_FLOAT_EQ(plain.emission.x, 0.2f);
    EXPECT_FLOAT_EQ(plain.emission.y, 0.4f);
    EXPECT_FLOAT_EQ(plain.emission.z, 0.6f);
    EXPECT_EQ(glm::vec3(plain.baseColor), glm::vec3(0.0f));
    EXPECT_EQ(plain.baseColor.w, 1.0f);
    EXPECT_EQ(plain.specular, 0.0f);
    EXPECT_EQ(plain.metallic, 0.0f);
    EXPECT_EQ(plain.emissiveTexture, WF_NO_TEXTURE);
    const Material textured = load("unlit_textured.gltf").materials[0];
    EXPECT_NE(textured.baseColorTexture, WF_NO_TEXTURE);
    EXPECT_EQ(textured.emissiveTexture, textured.baseColorTexture);
    EXPECT_EQ(textured.emission, glm::vec3(1.0f));
}

TEST(GltfFeatures, MissingImagesShowACheckerAndDropOtherUses) {
    Scene scene = load("missing_image_warns.gltf");
    ASSERT_EQ(scene.surface.images.size(), 1u);
    EXPECT_EQ(scene.surface.images[0].rgba[0], 0xffff00ffu); // magenta
    EXPECT_EQ(scene.materials[0].baseColorTexture, 0u);
}

TEST(GltfFeatures, GeneratedTangentsFollowTheUvs) {
    Scene scene = load("normal_map_generated_tangents.gltf");
    ASSERT_EQ(scene.surface.tangents.size(), 2u);
    for (const TriangleTangents& t : scene.surface.tangents) {
        expectNear(decode(t.t0), {1, 0, 0}, 1e-3f); // u grows along +x
        EXPECT_EQ(t.signs, 0u); // v grows along -y: an unmirrored mapping
    }
    Scene given = load("normal_map_with_tangents.gltf");
    expectNear(decode(given.surface.tangents[0].t2), {1, 0, 0}, 1e-3f);
    expectNear(decode(given.surface.normals[0].n0), {0, 0, 1}, 1e-3f);
    EXPECT_EQ(given.materials[0].normalTexture, 0u);
    EXPECT_NEAR(load("normal_map_generated_tangents.gltf").materials[0].normalScale, 0.8f, 1e-6f);
}

TEST(GltfFeatures, PunctualLightsInWorldSpace) {
    Scene scene = load("lights_punctual_and_sphere.gltf");
    ASSERT_EQ(scene.lights.size(), 4u); // the bad spot and the area light are skipped
    const PunctualLight& point = scene.lights[0];
    EXPECT_EQ(point.type, WF_LIGHT_POINT);
    expectNear(point.position, {0, 2, 0});
    expectNear(point.intensity, {10, 5, 2.5f});
    const PunctualLight& spot = scene.lights[1];
    EXPECT_EQ(spot.type, WF_LIGHT_SPOT);
    expectNear(spot.direction, {0, 0, -1});
    EXPECT_NEAR(spot.cosInner, std::cos(0.2f), 1e-6f);
    EXPECT_NEAR(spot.cosOuter, std::cos(0.5f), 1e-6f);
    EXPECT_EQ(scene.lights[2].type, WF_LIGHT_DIRECTIONAL);
    EXPECT_EQ(scene.lights[3].type, WF_LIGHT_SPHERE);
    EXPECT_FLOAT_EQ(scene.lights[3].radius, 0.25f);
    EXPECT_FALSE(scene.environment.present()); // lit scenes get no default sky
}

TEST(GltfFeatures, CamerasByNameAndDefaultSky) {
    Scene scene = load("cameras_some_invalid.gltf");
    ASSERT_EQ(scene.cameraNames.size(), 2u);
    EXPECT_EQ(scene.cameraNames[0], "front");
    EXPECT_EQ(scene.cameraNames[1], "cam3"); // unnamed camera: its node's name
    EXPECT_FLOAT_EQ(scene.cameras[1].aspect, 2.0f);
    expectNear(scene.camera.position, {0, 0, 3});
    ASSERT_TRUE(scene.environment.present()); // nothing emits: uniform white
    EXPECT_EQ(scene.environment.rgb, std::vector<float>({1, 1, 1}));
}

TEST(GltfFeatures, MaterialExtensions) {
    const Material m = load("material_extensions.gltf").materials[0];
    expectNear(m.emission, {5, 5, 5});
    EXPECT_FLOAT_EQ(m.ior, 1.33f);
    EXPECT_FLOAT_EQ(m.transmission, 0.5f);
    EXPECT_FLOAT_EQ(m.specular, 0.5f);
    expectNear(m.specularColor, {1, 0.9f, 0.8f});
    EXPECT_FLOAT_EQ(m.metallic, 0.2f);
    EXPECT_FLOAT_EQ(m.roughness, 0.3f);
    const Material mask = load("alpha_mask_all_textures.gltf").materials[0];
    EXPECT_EQ(mask.flags, WF_MATERIAL_DOUBLE_SIDED | WF_MATERIAL_ALPHA_MASK);
    EXPECT_FLOAT_EQ(mask.alphaCutoff, 0.4f);
    EXPECT_NE(mask.metallicRoughnessTexture, WF_NO_TEXTURE);
    EXPECT_NE(mask.emissiveTexture, WF_NO_TEXTURE);
    EXPECT_EQ(load("alpha_blend.gltf").materials[0].flags, WF_MATERIAL_ALPHA_BLEND);
}

// KHR_materials_clearcoat, _sheen, _volume and the specular textures reach the Material,
// the coat's texture too, without a warning (test_gltf_layer_textures.cpp has the others).
TEST(GltfFeatures, MaterialLayerExtensions) {
    ::testing::internal::CaptureStderr();
    const Scene scene = load("material_layers.gltf");
    const std::string err = ::testing::internal::GetCapturedStderr();
    const Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.clearcoat, 0.8f);
    EXPECT_FLOAT_EQ(m.clearcoatRoughness, 0.25f);
    expectNear(m.sheenColor, {0.5f, 0.4f, 0.3f});
    EXPECT_FLOAT_EQ(m.sheenRoughness, 0.6f);
    EXPECT_FLOAT_EQ(m.transmission, 1.0f);
    EXPECT_FLOAT_EQ(m.thickness, 0.2f);
    // sigma_a = -ln(attenuationColor) / attenuationDistance, distance 2.
    expectNear(m.attenuation, {std::log(2.0f) / 2, std::log(4.0f) / 2, 0.0f}, 1e-6f);
    EXPECT_FLOAT_EQ(m.specular, 0.9f);
    ASSERT_NE(m.specularTexture, WF_NO_TEXTURE);
    ASSERT_NE(m.specularColorTexture, WF_NO_TEXTURE);
    EXPECT_FALSE(scene.surface.textureRefs[m.specularTexture].flags & WF_TEXTURE_SRGB);
    EXPECT_TRUE(scene.surface.textureRefs[m.specularColorTexture].flags & WF_TEXTURE_SRGB);
    ASSERT_NE(m.clearcoatTexture, WF_NO_TEXTURE);
    EXPECT_EQ(err, "");
    // Without the extensions: no coat, sheen or absorption, no specular maps.
    const Material plain = load("material_extensions.gltf").materials[0];
    EXPECT_EQ(plain.clearcoat, 0.0f);
    EXPECT_EQ(plain.sheenColor, glm::vec3(0.0f));
    EXPECT_EQ(plain.attenuation, glm::vec3(0.0f));
    EXPECT_EQ(plain.thickness, 0.0f);
    EXPECT_EQ(plain.specularTexture, WF_NO_TEXTURE);
    EXPECT_EQ(plain.specularColorTexture, WF_NO_TEXTURE);
}

// KHR_materials_iridescence reaches the Material: factors, and both textures (the thickness
// one with its KHR_texture_transform); without the extension, the spec's defaults and no film.
TEST(GltfFeatures, MaterialIridescence) {
    const Scene scene = load("material_iridescence.gltf");
    const Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.iridescence, 0.7f);
    EXPECT_FLOAT_EQ(m.iridescenceIor, 1.8f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMinimum, 150.0f);
    EXPECT_FLOAT_EQ(m.iridescenceThicknessMaximum, 500.0f);
    ASSERT_NE(m.iridescenceTexture, WF_NO_TEXTURE);
    ASSERT_NE(m.iridescenceThicknessTexture, WF_NO_TEXTURE);
    EXPECT_FALSE(scene.surface.textureRefs[m.iridescenceTexture].flags & WF_TEXTURE_SRGB);
    EXPECT_FLOAT_EQ(scene.surface.textureRefs[m.iridescenceThicknessTexture].uRow.x, 2.0f);
    EXPECT_FLOAT_EQ(scene.surface.textureRefs[m.iridescenceTexture].uRow.x, 1.0f);
    const Material plain = load("material_extensions.gltf").materials[0];
    EXPECT_EQ(plain.iridescence, 0.0f);
    EXPECT_FLOAT_EQ(plain.iridescenceIor, 1.3f);
    EXPECT_FLOAT_EQ(plain.iridescenceThicknessMinimum, 100.0f);
    EXPECT_FLOAT_EQ(plain.iridescenceThicknessMaximum, 400.0f);
    EXPECT_EQ(plain.iridescenceTexture, WF_NO_TEXTURE);
    EXPECT_EQ(plain.iridescenceThicknessTexture, WF_NO_TEXTURE);
}

// KHR_materials_anisotropy reaches the Material: strength, rotation as (cos, sin), the texture
// (linear, with its KHR_texture_transform); the primitive, which has neither TANGENT nor a
// normal map, gets generated tangent frames. Without the extension: isotropic, no texture.
TEST(GltfFeatures, MaterialAnisotropy) {
    const Scene scene = load("material_anisotropy.gltf");
    const Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.anisotropyStrength, 0.6f);
    EXPECT_FLOAT_EQ(m.anisotropyRotation.x, std::cos(0.5f));
    EXPECT_FLOAT_EQ(m.anisotropyRotation.y, std::sin(0.5f));
    ASSERT_NE(m.anisotropyTexture, WF_NO_TEXTURE);
    EXPECT_FALSE(scene.surface.textureRefs[m.anisotropyTexture].flags & WF_TEXTURE_SRGB);
    EXPECT_FLOAT_EQ(scene.surface.textureRefs[m.anisotropyTexture].uRow.x, 3.0f);
    EXPECT_EQ(m.normalTexture, WF_NO_TEXTURE);
    EXPECT_EQ(scene.surface.tangents.size(), scene.triangles.size());
    const Material plain = load("material_extensions.gltf").materials[0];
    EXPECT_EQ(plain.anisotropyStrength, 0.0f);
    EXPECT_EQ(plain.anisotropyTexture, WF_NO_TEXTURE);
    EXPECT_EQ(plain.anisotropyRotation, glm::vec2(1.0f, 0.0f));
    EXPECT_TRUE(load("material_extensions.gltf").surface.tangents.empty());
}

// KHR_materials_diffuse_transmission reaches the Material: factor, colour, the factor's texture
// (linear, A, with its KHR_texture_transform) and the colour's (sRGB). Without the extension:
// factor 0, white, no textures.
TEST(GltfFeatures, MaterialDiffuseTransmission) {
    EXPECT_TRUE(gltf::isSupportedExtension("KHR_materials_diffuse_transmission"));
    testing::internal::CaptureStderr();
    const Scene scene = load("material_diffuse_transmission.gltf");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), ""); // no "ignoring glTF extension"
    const Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.diffuseTransmission, 0.6f);
    EXPECT_EQ(m.diffuseTransmissionColor, glm::vec3(1.0f, 0.5f, 0.25f));
    ASSERT_NE(m.diffuseTransmissionTexture, WF_NO_TEXTURE);
    ASSERT_NE(m.diffuseTransmissionColorTexture, WF_NO_TEXTURE);
    const TextureRef& factor = scene.surface.textureRefs[m.diffuseTransmissionTexture];
    const TextureRef& colour = scene.surface.textureRefs[m.diffuseTransmissionColorTexture];
    EXPECT_FALSE(factor.flags & WF_TEXTURE_SRGB);
    EXPECT_TRUE(colour.flags & WF_TEXTURE_SRGB);
    expectNear(factor.uRow, {2.0f, 0.0f, 0.5f});
    expectNear(factor.vRow, {0.0f, 2.0f, 0.0f});
    expectNear(colour.uRow, {1.0f, 0.0f, 0.0f});
    const Material plain = load("material_extensions.gltf").materials[0];
    EXPECT_EQ(plain.diffuseTransmission, 0.0f);
    EXPECT_EQ(plain.diffuseTransmissionColor, glm::vec3(1.0f));
    EXPECT_EQ(plain.diffuseTransmissionTexture, WF_NO_TEXTURE);
    EXPECT_EQ(plain.diffuseTransmissionColorTexture, WF_NO_TEXTURE);
}

TEST(GltfFeatures, MaterialDispersion) {
    EXPECT_TRUE(gltf::isSupportedExtension("KHR_materials_dispersion"));
    testing::internal::CaptureStderr();
    const Scene scene = load("material_dispersion.gltf");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), ""); // no "ignoring glTF extension"
    const Material& m = scene.materials[0];
    EXPECT_FLOAT_EQ(m.dispersion, 0.5f);
    EXPECT_FLOAT_EQ(m.ior, 1.6f);
    EXPECT_TRUE(gpu_types::materialDisperses(m));
    const Material plain = load("material_extensions.gltf").materials[0];
    EXPECT_EQ(plain.dispersion, 0.0f);
    EXPECT_FALSE(gpu_types::materialDisperses(plain));
}

TEST(GltfFeatures, UnknownExtensionsWarnOnceEach) {
    ::testing::internal::CaptureStderr();
    load("unknown_extensions_warn.gltf");
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("EXT_unknown_thing"), std::string::npos) << err;
    EXPECT_NE(err.find("KHR_materials_unknown_future"), std::string::npos) << err;
    EXPECT_EQ(err.find("EXT_unknown_thing"), err.rfind("EXT_unknown_thing")) << err;
}

} // namespace
} // namespace wf
