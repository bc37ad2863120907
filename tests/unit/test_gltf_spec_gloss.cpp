// KHR_materials_pbrSpecularGlossiness (archived) mapped onto the glTF BSDF: factors, the
// precedence over pbrMetallicRoughness, the F0 the BSDF forms from the mapped fields, the
// textures (diffuse as base colour, the specular colour read as sRGB, a roughness image made
// from the glossiness alpha), and materials without the extension left as they were.
#include <gtest/gtest.h>
#include <stb_image_write.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "errors.h"
#include "mini_gltf.h"
#include "scene/gltf/gltf_loader.h"
#include "shaders/bsdf/bsdf.h"

namespace wf {
namespace {

using test::F32;
using test::MiniGltf;
using test::TempDir;

const std::string USED = R"(,"extensionsUsed":["KHR_materials_pbrSpecularGlossiness"])";

// One triangle with UVs, material 0.
MiniGltf texturedTriangle(const std::string& material) {
    MiniGltf g;
    const std::vector<float> uv = {0, 0, 1, 0, 0, 1};
    const int uvs = g.addAccessor(g.addView(uv.data(), uv.size() * sizeof(float)), F32, 3, "VEC2");
    g.addMesh(g.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0}), -1, 0, 4,
              ",\"TEXCOORD_0\":" + std::to_string(uvs));
    g.nodes.push_back(R"({"mesh":0})");
    g.materials.push_back(material);
    g.extra = USED;
    return g;
}

// Loads the file and returns what it printed on stderr in `err`.
Scene loadCapturing(const std::string& path, std::string& err) {
    ::testing::internal::CaptureStderr();
    Scene scene = loadGltf(path);
    err = ::testing::internal::GetCapturedStderr();
    return scene;
}

// The BSDF parameters a loaded material's untextured fields give (shaders/bsdf/bsdf.h).
gpu_types::BsdfParams bsdfParamsOf(const Material& m) {
    gpu_types::BsdfParams p{};
    p.baseColor = glm::vec3(m.baseColor);
    p.metallic = m.metallic;
    p.roughness = m.roughness;
    p.ior = m.ior;
    p.transmission = m.transmission;
    p.specular = m.specular;
    p.specularColor = m.specularColor;
    return p;
}

// The dielectric F0 the BSDF forms from them.
glm::vec3 bsdfF0(const Material& m) {
    const gpu_types::BsdfParams p = bsdfParamsOf(m);
    return gpu_types::bsdfLobes(gpu_types::bsdfSanitize(p), false).f0 * p.specular;
}

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(GltfSpecGloss, FactorsMapOntoTheBsdfAndTakePrecedence) {
    TempDir dir;
    MiniGltf g = texturedTriangle(R"({
        "pbrMetallicRoughness":{"baseColorFactor":[1,0,0,1],"metallicFactor":1,
                                "roughnessFactor":0.2},
        "extensions":{"KHR_materials_pbrSpecularGlossiness":{
            "diffuseFactor":[0.5,0.25,0.125,0.75],"specularFactor":[0.2,0.1,0.05],
            "glossinessFactor":0.7}}})");
    std::string err;
    const Material m = loadCapturing(g.write(dir), err).materials[0];
    EXPECT_EQ(err.find("pbrSpecularGlossiness"), std::string::npos) << err;
    EXPECT_EQ(err.find("ignoring"), std::string::npos) << err;
    EXPECT_EQ(m.baseColor, glm::vec4(0.5f, 0.25f, 0.125f, 0.75f));
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_FLOAT_EQ(m.roughness, 0.3f);
    EXPECT_EQ(m.ior, 1.5f);
    EXPECT_EQ(m.specular, 1.0f);
    EXPECT_EQ(m.transmission, 0.0f);
    expectNear(bsdfF0(m), {0.2f, 0.1f, 0.05f}, 1e-6f);
    EXPECT_EQ(m.baseColorTexture, WF_NO_TEXTURE);
    EXPECT_EQ(m.metallicRoughnessTexture, WF_NO_TEXTURE);
    EXPECT_EQ(m.specularColorTexture, WF_NO_TEXTURE);
}

// The extension's defaults: white diffuse, white specular, glossiness 1: a perfect mirror
// (F0 = 1 through the BSDF's clamp).
TEST(GltfSpecGloss, DefaultsAreAWhiteMirror) {
    TempDir dir;
    MiniGltf g = texturedTriangle(R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{}}})");
    const Material m = loadGltf(g.write(dir)).materials[0];
    EXPECT_EQ(m.baseColor, glm::vec4(1.0f));
    EXPECT_EQ(m.roughness, 0.0f);
    EXPECT_EQ(m.metallic, 0.0f);
    expectNear(bsdfF0(m), glm::vec3(1.0f), 1e-6f);
}

TEST(GltfSpecGloss, FactorsOutsideTheirRangeAreRefused) {
    for (const char* member : {R"("glossinessFactor":1.5)", R"("specularFactor":[0,2,0])",
                               R"("diffuseFactor":[0,0,-1,1])"}) {
        TempDir dir;
        MiniGltf g = texturedTriangle(std::string(
            R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{)") + member + "}}}");
        const std::string path = g.write(dir);
        try {
            loadGltf(path);
            ADD_FAILURE() << "no InputError for " << member;
        } catch (const InputError& e) {
            const std::string key = std::string(member).substr(1, std::string(member).find('"', 1) - 1);
            EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        }
    }
}

// A 2x2 RGBA PNG of `texels` (R first) at dir/name.
void writeRgbaPng(const TempDir& dir, const std::string& name, const std::vector<uint8_t>& texels) {
    ASSERT_TRUE(stbi_write_png(dir.file(name).c_str(), 2, 2, 4, texels.data(), 8));
}

uint32_t packed(const uint8_t* rgba) {
    return uint32_t(rgba[0]) | uint32_t(rgba[1]) << 8 | uint32_t(rgba[2]) << 16 |
           uint32_t(rgba[3]) << 24;
}

TEST(GltfSpecGloss, TexturesBecomeBaseColourSpecularColourAndRoughness) {
    TempDir dir;
    const std::vector<uint8_t> diffuse = {200, 100, 50, 255, 10, 20, 30, 128,
                                          0, 0, 0, 0, 255, 255, 255, 255};
    const std::vector<uint8_t> specGloss = {60, 30, 15, 0, 255, 255, 255, 255,
                                            128, 64, 32, 128, 1, 2, 3, 64};
    writeRgbaPng(dir, "diffuse.png", diffuse);
    writeRgbaPng(dir, "specgloss.png", specGloss);
    writeRgbaPng(dir, "fallback.png", diffuse);
    MiniGltf g = texturedTriangle(R"({
        "pbrMetallicRoughness":{"baseColorTexture":{"index":2},
                                "metallicRoughnessTexture":{"index":2}},
        "extensions":{"KHR_materials_pbrSpecularGlossiness":{
            "diffuseTexture":{"index":0},"specularFactor":[0.5,0.25,1],"glossinessFactor":0.5,
            "specularGlossinessTexture":{"index":1,"extensions":{
                "KHR_texture_transform":{"offset":[0.25,0]}}}}}})");
    g.images = {R"({"uri":"diffuse.png"})", R"({"uri":"specgloss.png"})",
                R"({"uri":"fallback.png"})"};
    g.textures = {R"({"source":0})", R"({"source":1})", R"({"source":2})"};
    std::string err;
    const Scene scene = loadCapturing(g.write(dir), err);
    EXPECT_EQ(err, "");
    const Material& m = scene.materials[0];
    const SurfaceData& s = scene.surface;
    // The fallback's image is never decoded: diffuse, specular-glossiness, and the one made.
    ASSERT_EQ(s.images.size(), 3u);
    ASSERT_NE(m.baseColorTexture, WF_NO_TEXTURE);
    ASSERT_NE(m.specularColorTexture, WF_NO_TEXTURE);
    ASSERT_NE(m.metallicRoughnessTexture, WF_NO_TEXTURE);
    EXPECT_EQ(m.specularTexture, WF_NO_TEXTURE);
    EXPECT_EQ(m.metallic, 0.0f);
    EXPECT_EQ(m.roughness, 1.0f); // the made texture holds 1 - glossiness
    expectNear(bsdfF0(m), {0.5f, 0.25f, 1.0f}, 1e-6f);

    const TextureImage& base = s.images[s.refImage[m.baseColorTexture]];
    EXPECT_TRUE(s.textureRefs[m.baseColorTexture].flags & WF_TEXTURE_SRGB);
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(base.rgba[i], packed(&diffuse[4 * i])) << i;

    const TextureRef& colourRef = s.textureRefs[m.specularColorTexture];
    const TextureImage& colour = s.images[s.refImage[m.specularColorTexture]];
    EXPECT_TRUE(colourRef.flags & WF_TEXTURE_SRGB);
    EXPECT_EQ(colourRef.uRow, glm::vec3(1, 0, 0.25f));
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(colour.rgba[i], packed(&specGloss[4 * i])) << i;

    const TextureRef& roughRef = s.textureRefs[m.metallicRoughnessTexture];
    const TextureImage& rough = s.images[s.refImage[m.metallicRoughnessTexture]];
    EXPECT_FALSE(roughRef.flags & WF_TEXTURE_SRGB);
    EXPECT_EQ(roughRef.uRow, glm::vec3(1, 0, 0.25f));
    ASSERT_EQ(rough.width, 2u);
    ASSERT_EQ(rough.height, 2u);
    // G = round(255 (1 - 0.5 A / 255)); R 255, B 0 (metallic), A 255.
    const uint8_t expected[4] = {255, 128, 191, 223};
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(rough.rgba[i], 0xff0000ffu | uint32_t(expected[i]) << 8) << i;
}

// Two materials sharing the texture and glossiness share the image made from it.
TEST(GltfSpecGloss, OneRoughnessImagePerTextureAndFactor) {
    TempDir dir;
    writeRgbaPng(dir, "specgloss.png", std::vector<uint8_t>(16, 77));
    const std::string material = R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{
        "glossinessFactor":0.25,"specularGlossinessTexture":{"index":0}}}})";
    MiniGltf g = texturedTriangle(material);
    g.materials.push_back(material);
    g.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":1,"TEXCOORD_0":0},
                                          "material":1}]})");
    g.nodes.push_back(R"({"mesh":1})");
    g.scenes = R"([{"nodes":[0,1]}])";
    g.images = {R"({"uri":"specgloss.png"})"};
    g.textures = {R"({"source":0})"};
    const Scene scene = loadGltf(g.write(dir));
    EXPECT_EQ(scene.surface.images.size(), 2u);
    EXPECT_EQ(scene.surface.refImage[scene.materials[0].metallicRoughnessTexture],
              scene.surface.refImage[scene.materials[1].metallicRoughnessTexture]);
}

// The specular-glossiness model sets F0 itself: KHR_materials_ior and _specular beside it are
// ignored, with a warning.
TEST(GltfSpecGloss, IorAndSpecularBesideItAreIgnored) {
    TempDir dir;
    MiniGltf g = texturedTriangle(R"({"extensions":{
        "KHR_materials_pbrSpecularGlossiness":{"specularFactor":[0.04,0.04,0.04]},
        "KHR_materials_ior":{"ior":2.0},"KHR_materials_specular":{"specularFactor":0.5}}})");
    std::string err;
    const Material m = loadCapturing(g.write(dir), err).materials[0];
    EXPECT_NE(err.find("KHR_materials_ior is ignored"), std::string::npos) << err;
    EXPECT_NE(err.find("KHR_materials_specular is ignored"), std::string::npos) << err;
    expectNear(bsdfF0(m), glm::vec3(0.04f), 1e-7f);
}

// White furnace on the CPU (the BSDF header the shade pass compiles): spec-gloss materials as
// loaded, white diffuse with white or coloured specular at several glossinesses, reflect at
// most what they receive at every angle.
TEST(GltfSpecGloss, WhiteFurnaceAlbedoAtMostOne) {
    for (const char* specular : {"[1,1,1]", "[0.5,0.5,0.5]", "[1,0.2,0]", "[0.04,0.04,0.04]"}) {
        for (const char* glossiness : {"1", "0.8", "0.5", "0"}) {
            TempDir dir;
            MiniGltf g = texturedTriangle(
                std::string(R"({"extensions":{"KHR_materials_pbrSpecularGlossiness":{
                "diffuseFactor":[1,1,1,1],"specularFactor":)") + specular +
                ",\"glossinessFactor\":" + glossiness + "}}}");
            const Material m = loadGltf(g.write(dir)).materials[0];
            gpu_types::BsdfParams p = bsdfParamsOf(m);
            for (float cosTheta : {1.0f, 0.7f, 0.3f, 0.05f}) {
                const glm::vec3 wo(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
                std::mt19937 rng(7u);
                std::uniform_real_distribution<float> u(0.0f, 1.0f);
                glm::dvec3 sum(0.0), sum2(0.0);
                const int n = 20000;
                for (int i = 0; i < n; ++i) {
                    gpu_types::BsdfSample s;
                    const float uLobe = u(rng);
                    const glm::vec2 uDir(u(rng), u(rng));
                    if (gpu_types::bsdfSample(p, wo, uLobe, uDir, s)) {
                        const glm::dvec3 w(s.weight);
                        sum += w;
                        sum2 += w * w;
                    }
                }
                const glm::dvec3 mean = sum / double(n);
                const glm::dvec3 err =
                    glm::sqrt(glm::max(sum2 / double(n) - mean * mean, 0.0) / double(n));
                for (int k = 0; k < 3; ++k)
                    EXPECT_LE(mean[k], 1.0 + 4.0 * err[k] + 3e-3)
                        << specular << " glossiness " << glossiness << " cos " << cosTheta;
            }
        }
    }
}

// Without the extension the metallic-roughness material reads as before: its own factors and
// textures, the file's images only, nothing made.
TEST(GltfSpecGloss, WithoutItMetallicRoughnessIsUnchanged) {
    TempDir dir;
    const std::vector<uint8_t> texels = {60, 30, 15, 0, 255, 255, 255, 255,
                                         128, 64, 32, 128, 1, 2, 3, 64};
    writeRgbaPng(dir, "mr.png", texels);
    MiniGltf g = texturedTriangle(R"({"pbrMetallicRoughness":{"baseColorFactor":[1,0.5,0,1],
        "metallicFactor":0.25,"roughnessFactor":0.5,"metallicRoughnessTexture":{"index":0}}})");
    g.extra = "";
    g.images = {R"({"uri":"mr.png"})"};
    g.textures = {R"({"source":0})"};
    const Scene scene = loadGltf(g.write(dir));
    const Material& m = scene.materials[0];
    EXPECT_EQ(m.baseColor, glm::vec4(1, 0.5f, 0, 1));
    EXPECT_EQ(m.metallic, 0.25f);
    EXPECT_EQ(m.roughness, 0.5f);
    EXPECT_EQ(m.specular, 1.0f);
    EXPECT_EQ(m.specularColor, glm::vec3(1.0f));
    EXPECT_EQ(m.specularColorTexture, WF_NO_TEXTURE);
    ASSERT_EQ(scene.surface.images.size(), 1u);
    ASSERT_EQ(scene.surface.textureRefs.size(), 1u);
    EXPECT_EQ(m.metallicRoughnessTexture, 0u);
    EXPECT_FALSE(scene.surface.textureRefs[0].flags & WF_TEXTURE_SRGB);
    for (int i = 0; i < 4; ++i)
        EXPECT_EQ(scene.surface.images[0].rgba[i], packed(&texels[4 * i])) << i;
}

} // namespace
} // namespace wf
