// EXT_texture_webp through Debian's libwebp: a lossless 4x4 WebP in a bufferView, named only by
// the texture's extension (no PNG fallback `source`), comes back texel for texel; a texture
// whose extension names no image is refused in one line; broken WebP bytes give the checker.
#include <gtest/gtest.h>
#include <webp/encode.h>

#include <cstring>

#include "errors.h"
#include "mini_gltf.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {
namespace {

std::vector<uint8_t> losslessWebp(const std::vector<uint8_t>& rgba, int width, int height) {
    uint8_t* out = nullptr;
    const size_t size = WebPEncodeLosslessRGBA(rgba.data(), width, height, width * 4, &out);
    std::vector<uint8_t> bytes(out, out + size);
    WebPFree(out);
    return bytes;
}

std::string webpScene(const test::TempDir& dir, const std::vector<uint8_t>& image,
                      const std::string& source = "0") {
    test::MiniGltf g;
    const int pos = g.addPositions({0, 0, 0, 1, 0, 0, 1, 1, 0});
    const std::vector<float> uv = {0, 0, 1, 0, 1, 1};
    const int uvs = g.addAccessor(g.addView(uv.data(), uv.size() * 4), test::F32, 3, "VEC2");
    const int view = g.addView(image.data(), image.size());
    g.images.push_back("{\"bufferView\":" + std::to_string(view) + ",\"mimeType\":\"image/webp\"}");
    g.textures.push_back("{\"extensions\":{\"EXT_texture_webp\":{\"source\":" + source + "}}}");
    g.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}})");
    g.addMesh(pos, -1, 0, 4, ",\"TEXCOORD_0\":" + std::to_string(uvs));
    g.nodes = {R"({"mesh":0})"};
    g.extra = R"(,"extensionsUsed":["EXT_texture_webp"],"extensionsRequired":["EXT_texture_webp"])";
    return g.write(dir);
}

TEST(Webp, LosslessTexelsComeBackExactly) {
    std::vector<uint8_t> rgba(4 * 4 * 4);
    for (size_t i = 0; i < rgba.size(); ++i)
        rgba[i] = uint8_t(i * 37 + 11);
    for (size_t i = 3; i < rgba.size(); i += 4)
        rgba[i] = 255; // opaque: lossless WebP may change the colour of transparent texels
    test::TempDir dir;
    std::vector<std::string> warnings;
    const Scene scene = loadGltf(webpScene(dir, losslessWebp(rgba, 4, 4)), &warnings);
    ASSERT_EQ(scene.surface.images.size(), 1u);
    const TextureImage& image = scene.surface.images[0];
    ASSERT_EQ(image.width, 4u);
    ASSERT_EQ(image.height, 4u);
    EXPECT_EQ(std::memcmp(image.rgba.data(), rgba.data(), rgba.size()), 0);
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(Webp, BrokenWebpShowsTheCheckerAndABadSourceIsRefused) {
    test::TempDir dir;
    std::vector<uint8_t> broken = {'R', 'I', 'F', 'F', 40, 0, 0, 0, 'W', 'E', 'B', 'P', 1, 2, 3};
    std::vector<std::string> warnings;
    const Scene scene = loadGltf(webpScene(dir, broken), &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("unreadable WebP header"), std::string::npos) << warnings[0];
    EXPECT_EQ(scene.surface.images.at(0).name, "missing-image checker");
    try {
        loadGltf(webpScene(dir, broken, "4"));
        FAIL() << "an out-of-range EXT_texture_webp source was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("EXT_texture_webp source must name one of the 1 "
                                             "images"),
                  std::string::npos)
            << e.what();
    }
}

} // namespace
} // namespace wf
