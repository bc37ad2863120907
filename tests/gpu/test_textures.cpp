// Textures, vertex attributes and alpha on the GPU: a scene without them compiles no texture
// code and binds no such buffer; emissive textures come out sRGB-decoded, wrapped and
// transformed as glTF says; alpha cut-outs stop neither camera nor shadow rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gpu_test_util.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_materials.h"

namespace wf::test {
namespace {

bool spirvMentions(const std::vector<uint32_t>& spirv, const char* name) {
    const char* bytes = reinterpret_cast<const char*>(spirv.data());
    const std::string text(bytes, spirv.size() * 4);
    return text.find(name) != std::string::npos;
}

// An axis-aligned quad at depth z facing +z (towards a camera at the origin looking at -z).
void addQuad(Scene& scene, float z, float halfSize, uint32_t material, float x0 = 0.0f) {
    const glm::vec3 a(x0 - halfSize, -halfSize, z), b(x0 + halfSize, -halfSize, z),
        c(x0 + halfSize, halfSize, z), d(x0 - halfSize, halfSize, z);
    scene.triangles.push_back({a, material, b, WF_NO_EMITTER, c, 0});
    scene.triangles.push_back({a, material, c, WF_NO_EMITTER, d, 0});
    // glTF UVs: (0, 0) is the image's top-left corner.
    scene.surface.uv0.push_back({{0, 1}, {1, 1}, {1, 0}});
    scene.surface.uv0.push_back({{0, 1}, {1, 0}, {0, 0}});
}

Scene cameraFacingQuads() {
    Scene scene;
    scene.camera.position = glm::vec3(0.0f);
    scene.camera.forward = glm::vec3(0, 0, -1);
    scene.camera.up = glm::vec3(0, 1, 0);
    scene.camera.yfov = 2.0f * std::atan(0.5f); // the quad at z = -1 of half size 0.5 fills it
    scene.hasCamera = true;
    return scene;
}

Material emissive(glm::vec3 emission) {
    Material m = gltf::defaultMaterial();
    m.baseColor = glm::vec4(0, 0, 0, 1);
    m.emission = emission;
    return m;
}

TextureRef ref(uint32_t flags) {
    TextureRef r{};
    r.uRow = glm::vec3(1, 0, 0);
    r.vRow = glm::vec3(0, 1, 0);
    r.flags = flags;
    return r;
}

RenderSettings settings(uint32_t size, uint32_t spp, uint32_t depth) {
    RenderSettings s;
    s.width = s.height = size;
    s.samplesPerPixel = spp;
    s.maxDepth = depth;
    return s;
}

const float* pixel(const RenderResult& r, uint32_t size, uint32_t x, uint32_t y) {
    return &r.rgb[3 * (size_t(y) * size + x)];
}

TEST(Textures, SceneWithoutTexturesHasNoTextureCodeOrBuffers) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf");
    PreparedScene prepared = prepareScene(std::move(scene));
    ShaderCompiler compiler(defaultShaderDir(), "");
    WavefrontRenderer renderer(gpuContext(), prepared, settings(8, 1, 2), compiler);
    const ShaderDefines& defines = renderer.shaderDefines();
    for (const char* name : {"WF_HAS_TEXTURES", "WF_HAS_NORMALS", "WF_HAS_NORMAL_MAPS",
                             "WF_HAS_ALPHA_MASK", "WF_HAS_TEXCOORD1", "WF_RAY_CONES"}) {
        auto it = std::find_if(defines.begin(), defines.end(),
                               [&](const auto& d) { return d.first == name; });
        ASSERT_NE(it, defines.end()) << name;
        EXPECT_EQ(it->second, "0") << name;
    }
    for (const auto& [name, bytes] : renderer.memoryReport()) {
        for (const char* word :
             {"texel", "texture", "texcoords", "normals", "tangents", "cones"}) {
            EXPECT_EQ(name.find(word), std::string::npos) << name;
        }
    }
    // The compiled code itself: no texture buffer or sampling function in any pass...
    for (const char* pass : {"raygen.comp", "shade.comp", "intersect.comp", "shadow.comp",
                             "megakernel.comp"}) {
        const std::vector<uint32_t> spirv = compiler.compile(pass, defines).spirv;
        for (const char* name : {"texelPage0", "textureRefTexels", "texcoord0TexelPage0",
                                 "normalTexelPage0", "sampleTexture", "wfAlphaPasses", "rayCone",
                                 "mipLevel"}) {
            EXPECT_FALSE(spirvMentions(spirv, name)) << pass << " has " << name;
        }
    }
    // ... while the textured variant has them (so the check above can fail).
    ShaderDefines textured = defines;
    for (auto& [name, value] : textured) {
        if (name == "WF_HAS_TEXTURES" || name == "WF_HAS_ALPHA_MASK" ||
            name == "WF_HAS_NORMALS" || name == "WF_HAS_NORMAL_MAPS")
            value = "1";
        if (name == "WF_TEXEL_PAGES")
            value = "2";
        if (name == "WF_RAY_CONES")
            value = "1";
    }
    const std::vector<uint32_t> shade = compiler.compile("shade.comp", textured).spirv;
    EXPECT_TRUE(spirvMentions(shade, "texelPage1"));
    EXPECT_TRUE(spirvMentions(shade, "normalTexelPage0"));
    EXPECT_TRUE(spirvMentions(shade, "texcoord0TexelPage0"));
    EXPECT_TRUE(spirvMentions(shade, "rayConeTexels"));
    EXPECT_TRUE(spirvMentions(shade, "mipLevel"));
    EXPECT_TRUE(spirvMentions(compiler.compile("raygen.comp", textured).spirv, "rayCone"));
    EXPECT_TRUE(spirvMentions(compiler.compile("megakernel.comp", textured).spirv, "mipLevel"));
    EXPECT_TRUE(spirvMentions(compiler.compile("shadow.comp", textured).spirv, "wfAlphaPasses"));
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// Emission seen directly (max depth 1) is exactly emissiveFactor x texture: a 2x2 texture of
// known sRGB values, nearest filtering, shows each quadrant's linear value.
TEST(Textures, EmissiveTextureIsSrgbDecodedAndOriented) {
    Scene scene = cameraFacingQuads();
    Material m = emissive(glm::vec3(2.0f));
    m.emissiveTexture = 0;
    scene.materials.push_back(m);
    addQuad(scene, -1.0f, 0.5f, 0);
    TextureImage image;
    image.width = image.height = 2;
    // Top-left 255 red, top-right sRGB 128 grey, bottom-left black, bottom-right blue.
    image.rgba = {0xff0000ffu, 0xff808080u, 0xff000000u, 0xffff0000u};
    scene.surface.images.push_back(image);
    scene.surface.textureRefs.push_back(ref(WF_TEXTURE_SRGB | WF_TEXTURE_NEAREST));
    scene.surface.refImage.push_back(0);
    const uint32_t size = 16;
    RenderResult r = renderScene(scene, settings(size, 4, 1));
    const float grey = 2.0f * std::pow((128.0f / 255.0f + 0.055f) / 1.055f, 2.4f);
    EXPECT_NEAR(pixel(r, size, 3, 3)[0], 2.0f, 1e-3f);
    EXPECT_NEAR(pixel(r, size, 3, 3)[1], 0.0f, 1e-3f);
    EXPECT_NEAR(pixel(r, size, 12, 3)[1], grey, 1e-3f);
    EXPECT_NEAR(pixel(r, size, 3, 12)[0], 0.0f, 1e-3f);
    EXPECT_NEAR(pixel(r, size, 12, 12)[2], 2.0f, 1e-3f);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// Bilinear filtering and REPEAT wrapping with a KHR_texture_transform offset of half a texel
// row: a 2x1 texture black|white, linear data, sampled at u + 0.25 across the quad.
TEST(Textures, BilinearRepeatAndTransform) {
    Scene scene = cameraFacingQuads();
    Material m = emissive(glm::vec3(1.0f));
    m.emissiveTexture = 0;
    scene.materials.push_back(m);
    addQuad(scene, -1.0f, 0.5f, 0);
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0xff000000u, 0xffffffffu};
    scene.surface.images.push_back(image);
    TextureRef r0 = ref(WF_WRAP_REPEAT);
    r0.uRow = glm::vec3(1, 0, 0.25f); // u' = u + 0.25
    scene.surface.textureRefs.push_back(r0);
    scene.surface.refImage.push_back(0);
    const uint32_t size = 32;
    RenderResult r = renderScene(scene, settings(size, 16, 1));
    // At u' the filtered value is a triangle wave: 0 at u' = 0.25, 1 at u' = 0.75 (texel
    // centres), linear between, and it wraps. Pixel x covers u in [x, x+1) / size.
    for (uint32_t x = 0; x < size; ++x) {
        const float u = (x + 0.5f) / size + 0.25f;
        const float t = std::fmod(u + 0.75f, 1.0f); // 0 at a black centre
        const float expected = t < 0.5f ? 2.0f * t : 2.0f - 2.0f * t;
        EXPECT_NEAR(pixel(r, size, x, size / 2)[0], expected, 0.04f) << "x = " << x;
    }
}

// A masked quad in front of a green one: where alpha is below the cutoff the camera sees
// green; a BLEND quad of alpha 0.25 lets three quarters of the rays through.
TEST(Textures, AlphaCutOutsStopNoCameraRay) {
    Scene scene = cameraFacingQuads();
    Material front = emissive(glm::vec3(1, 0, 0));
    front.flags = WF_MATERIAL_ALPHA_MASK;
    front.alphaCutoff = 0.5f;
    front.baseColorTexture = 0;
    Material blend = emissive(glm::vec3(1, 0, 0));
    blend.flags = WF_MATERIAL_ALPHA_BLEND;
    blend.baseColor.w = 0.25f;
    scene.materials = {front, emissive(glm::vec3(0, 1, 0)), blend};
    addQuad(scene, -1.0f, 0.25f, 0, -0.25f); // left: masked by the texture
    addQuad(scene, -1.0f, 0.25f, 2, 0.25f);  // right: blended
    addQuad(scene, -2.0f, 2.0f, 1);         // green backdrop
    TextureImage image;
    image.width = 2;
    image.height = 1;
    image.rgba = {0x00ffffffu, 0xffffffffu}; // left texel transparent, right opaque
    scene.surface.images.push_back(image);
    scene.surface.textureRefs.push_back(ref(WF_TEXTURE_NEAREST | WF_WRAP_CLAMP));
    scene.surface.refImage.push_back(0);
    const uint32_t size = 32;
    RenderResult r = renderScene(scene, settings(size, 64, 1));
    EXPECT_NEAR(pixel(r, size, 3, 16)[1], 1.0f, 1e-4f);  // cut out: the backdrop
    EXPECT_NEAR(pixel(r, size, 12, 16)[0], 1.0f, 1e-4f); // opaque texel: the red quad
    double red = 0.0;
    for (uint32_t y = size / 4; y < 3 * size / 4; ++y) // the blended quad's pixels
        for (uint32_t x = size / 2; x < size; ++x)
            red += pixel(r, size, x, y)[0];
    EXPECT_NEAR(red / (size * size / 4), 0.25, 0.02);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// A fully cut-out occluder between an area light and a floor casts no shadow; an opaque one
// casts a full shadow. Depth 2: direct light only, through shadow rays and BSDF rays alike.
TEST(Textures, AlphaCutOutsStopNoShadowRay) {
    auto floorUnderLight = [](uint32_t occluderFlags) {
        Scene scene;
        Material floor = gltf::defaultMaterial();
        floor.flags = WF_MATERIAL_DOUBLE_SIDED;
        Material light = emissive(glm::vec3(4.0f));
        light.flags = WF_MATERIAL_DOUBLE_SIDED;
        Material occluder = gltf::defaultMaterial();
        occluder.flags = occluderFlags | WF_MATERIAL_DOUBLE_SIDED;
        occluder.baseColor.w = 0.0f;
        scene.materials = {floor, light, occluder};
        auto quadY = [&](float y, float half, uint32_t material) {
            const glm::vec3 a(-half, y, -half), b(half, y, -half), c(half, y, half),
                d(-half, y, half);
            scene.triangles.push_back({a, material, b, WF_NO_EMITTER, c, 0});
            scene.triangles.push_back({a, material, c, WF_NO_EMITTER, d, 0});
        };
        quadY(0.0f, 4.0f, 0);
        quadY(2.0f, 0.5f, 1);
        quadY(1.0f, 1.5f, 2);
        scene.camera.position = glm::vec3(0, 0.5f, 0);
        scene.camera.forward = glm::vec3(0, -1, 0);
        scene.camera.up = glm::vec3(0, 0, 1);
        scene.camera.yfov = 0.5f;
        scene.hasCamera = true;
        RenderResult r = renderScene(scene, settings(8, 64, 2));
        double sum = 0.0;
        for (size_t i = 0; i < r.rgb.size(); i += 3)
            sum += r.rgb[i];
        return sum / (r.rgb.size() / 3);
    };
    const double cutOut = floorUnderLight(WF_MATERIAL_ALPHA_MASK);
    const double opaque = floorUnderLight(0u);
    EXPECT_GT(cutOut, 0.1);
    EXPECT_LT(opaque, 0.02 * cutOut);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
