// Compressed copies of a scene render like the original: with the same seed the copy's image
// is closer to the original's than an independent render (another seed) of the original is,
// so quantization moves nothing beyond noise; the copy's bias is within the noise's; it
// compiles the original's shader variant. A control, a copy broken on purpose, fails the same
// check, so the check can fail.
// - gltfpack -cc (EXT_meshopt_compression over KHR_mesh_quantization, 14-bit positions) of
//   the Cornell box; the control lacks two triangles. Skipped where gltfpack is not installed
//   (scripts/setup.sh --with-tests installs it).
// - Draco and KHR meshopt copies (tests/gpu/compressed_copy.h) of the Cornell box with a
//   textured, smoothly shaded sphere added, so that normals and UVs go through the codecs as
//   well; the control's UVs are one checker cell off (the checker inverted). Each
//   material's area and centroid are checked too, which catches what renders at 40x40 take
//   for noise (8-bit Draco positions fail it; 6-bit ones still pass the image check).
#include <stb_image_write.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include "compressed_copy.h"
#include "gpu_test_util.h"
#include "image/error_metrics.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/shader_variant.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

namespace fs = std::filesystem;

RenderSettings settings(uint32_t seed) {
    RenderSettings s;
    s.width = 40;
    s.height = 40;
    s.samplesPerPixel = 64;
    s.maxDepth = 6;
    s.seed = seed;
    return s;
}

// Files live only while they are loaded, in a folder of this process's own (ctest may run
// these tests side by side).
fs::path tempFile(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("wf_test_compressed_scenes_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

Scene loadAndRemove(const fs::path& path) {
    Scene scene = loadGltf(path.string());
    std::error_code ignored;
    fs::remove(path, ignored);
    fs::remove(path.parent_path(), ignored); // once empty
    return scene;
}

// The original's renders at seed 1 (the reference) and seed 2 (its noise).
struct Reference {
    std::vector<float> rgb;
    ImageError noise;
    double mean = 0.0;
    std::string variant;

    explicit Reference(const Scene& original) : rgb(renderScene(original, settings(1)).rgb) {
        noise = imageError(renderScene(original, settings(2)).rgb, rgb);
        mean = imageMean(rgb).mean;
        variant = chooseVariant(prepareScene(original), settings(1)).describe();
    }
};

void expectRendersLike(const Reference& reference, const Scene& copy, const char* what) {
    // Decoded in the loader: the same shader variant as the original.
    EXPECT_EQ(chooseVariant(prepareScene(copy), settings(1)).describe(), reference.variant);
    const RenderResult result = renderScene(copy, settings(1));
    EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
    const ImageError error = imageError(result.rgb, reference.rgb);
    std::printf("relMSE against the original: %s %.3g, another seed %.3g; bias %.3g, %.3g\n",
                what, error.relMse, reference.noise.relMse, error.bias, reference.noise.bias);
    EXPECT_LT(error.relMse, reference.noise.relMse);
    EXPECT_LT(std::abs(error.bias), std::abs(reference.noise.bias) + 0.01 * reference.mean);
}

// Renders see sub-pixel moves as noise (6-bit Draco positions, moves of 0.1 on the 5.55 box,
// pass the image check), so the geometry is checked beside it: each material's area and
// area-weighted centroid as in the original, within what 14-bit quantization moves.
void expectSameSurfaces(const Scene& copy, const Scene& original) {
    const auto moments = [](const Scene& scene) {
        // Per material: centroid x area, area.
        std::vector<glm::dvec4> out(scene.materials.size(), glm::dvec4(0.0));
        for (const Triangle& t : scene.triangles) {
            const double area = 0.5 * glm::length(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
            out[t.material] += glm::dvec4(glm::dvec3(t.p0 + t.p1 + t.p2) / 3.0 * area, area);
        }
        return out;
    };
    ASSERT_EQ(copy.materials.size(), original.materials.size());
    const std::vector<glm::dvec4> a = moments(copy), b = moments(original);
    for (std::size_t m = 0; m < a.size(); ++m) {
        EXPECT_NEAR(a[m].w, b[m].w, 1e-3 * b[m].w) << "area of material " << m;
        if (b[m].w > 0.0) {
            EXPECT_LT(glm::distance(glm::dvec3(a[m]) / a[m].w, glm::dvec3(b[m]) / b[m].w), 1e-3)
                << "centroid of material " << m;
        }
    }
}

void expectControlCaught(const Reference& reference, const Scene& broken, const char* what) {
    const ImageError control = imageError(renderScene(broken, settings(1)).rgb, reference.rgb);
    std::printf("relMSE of %s: %.3g\n", what, control.relMse);
    EXPECT_GT(control.relMse, reference.noise.relMse) << what;
}

TEST(CompressedScenes, GltfpackCornellBoxRendersLikeTheOriginal) {
    if (std::system("gltfpack -v >/dev/null 2>&1") != 0) {
        GTEST_SKIP() << "gltfpack is not installed (scripts/setup.sh --with-tests)";
    }
    const std::string source = std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf";
    const fs::path packed = tempFile("cornell_box_cc.glb");
    const std::string command =
        "gltfpack -i '" + source + "' -o '" + packed.string() + "' -cc >/dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;

    const Scene original = loadGltf(source);
    const Scene compressed = loadAndRemove(packed);
    ASSERT_EQ(compressed.triangles.size(), original.triangles.size());
    EXPECT_EQ(compressed.surface.normals.size(), original.surface.normals.size());
    EXPECT_EQ(compressed.surface.uv0.size(), original.surface.uv0.size());
    const Reference reference(original);
    expectRendersLike(reference, compressed, "gltfpack -cc");

    // A wall's half missing is caught.
    Scene broken = compressed;
    broken.triangles.erase(broken.triangles.begin(), broken.triangles.begin() + 2);
    expectControlCaught(reference, broken, "the scene less two triangles");
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// A 16 x 16 PNG checker of 4 x 4 cells, dark and light.
std::vector<unsigned char> checkerPng() {
    std::vector<unsigned char> texels;
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            const unsigned char v = (x / 4 + y / 4) % 2 ? 235 : 40;
            texels.insert(texels.end(), {v, v, v});
        }
    }
    std::vector<unsigned char> png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<unsigned char>*>(context);
            out->insert(out->end(), static_cast<unsigned char*>(data),
                        static_cast<unsigned char*>(data) + size);
        },
        &png, 16, 16, 3, texels.data(), 16 * 3);
    return png;
}

constexpr int kCheckerCells = 4;

// scenes/cornell_box.gltf with a sphere of radius 1 on its floor, in front of the tall block:
// smooth normals, UVs of latitude and longitude, the checker as base colour, glossy.
Document cornellBoxWithSphere() {
    Document doc = readGltf(std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf");
    const int rings = 12, segments = 24;
    const glm::vec3 centre(3.9f, 1.0f, 1.15f);
    std::vector<float> positions, normals, uvs;
    for (int r = 0; r <= rings; ++r) {
        for (int s = 0; s <= segments; ++s) {
            const float theta = glm::pi<float>() * r / rings;
            const float phi = 2.0f * glm::pi<float>() * s / segments;
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            const glm::vec3 p = centre + n;
            positions.insert(positions.end(), {p.x, p.y, p.z});
            normals.insert(normals.end(), {n.x, n.y, n.z});
            uvs.insert(uvs.end(), {float(s) / segments, float(r) / rings});
        }
    }
    // Counter-clockwise seen from outside; none at the poles, where a ring is one point.
    std::vector<uint16_t> indices;
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const uint16_t a = uint16_t(r * (segments + 1) + s), b = a + 1,
                           c = uint16_t(a + segments + 1), d = c + 1;
            if (r + 1 < rings) {
                indices.insert(indices.end(), {a, d, c});
            }
            if (r > 0) {
                indices.insert(indices.end(), {a, b, d});
            }
        }
    }
    const std::size_t n = positions.size() / 3;
    const auto accessor = [&](const std::vector<float>& values, const char* type) {
        return doc.accessor({{"bufferView", doc.rawView(values.data(), values.size() * 4)},
                             {"componentType", 5126}, {"count", n}, {"type", type}});
    };
    const Json attributes = {{"POSITION", accessor(positions, "VEC3")},
                             {"NORMAL", accessor(normals, "VEC3")},
                             {"TEXCOORD_0", accessor(uvs, "VEC2")}};
    const int index =
        doc.accessor({{"bufferView", doc.rawView(indices.data(), indices.size() * 2)},
                      {"componentType", 5123}, {"count", indices.size()}, {"type", "SCALAR"}});
    const std::vector<unsigned char> png = checkerPng();
    doc.json["images"] = Json::array(
        {{{"bufferView", doc.rawView(png.data(), png.size())}, {"mimeType", "image/png"}}});
    doc.json["samplers"] = Json::array({{{"magFilter", 9728}, {"minFilter", 9728}}});
    doc.json["textures"] = Json::array({{{"source", 0}, {"sampler", 0}}});
    const Json pbr = {{"baseColorTexture", Json::object({{"index", 0}})},
                      {"metallicFactor", 0.0},
                      {"roughnessFactor", 0.4}};
    doc.json["materials"].push_back({{"name", "checker"}, {"pbrMetallicRoughness", pbr}});
    const Json primitive = {{"attributes", attributes},
                            {"indices", index},
                            {"material", doc.json["materials"].size() - 1}};
    doc.json["meshes"].push_back(
        {{"name", "sphere"}, {"primitives", Json::array({primitive})}});
    doc.json["nodes"].push_back({{"name", "sphere"}, {"mesh", doc.json["meshes"].size() - 1}});
    doc.json["scenes"][0]["nodes"].push_back(doc.json["nodes"].size() - 1);
    return doc;
}

class CompressedCopies : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        originalDocument = new Document(cornellBoxWithSphere());
        original = new Scene(loadAndRemove(originalDocument->write(tempFile("original.glb"))));
        reference = new Reference(*original);
    }
    static void TearDownTestSuite() {
        delete reference;
        delete original;
        delete originalDocument;
    }

    void expectCopyRendersLikeTheOriginal(MeshCodec codec, const char* name) {
        const Document copy = compressedCopy(*originalDocument, codec);
        const Scene compressed = loadAndRemove(copy.write(tempFile(std::string(name) + ".glb")));
        ASSERT_EQ(compressed.triangles.size(), original->triangles.size());
        ASSERT_EQ(compressed.surface.normals.size(), original->triangles.size());
        ASSERT_EQ(compressed.surface.uv0.size(), original->triangles.size());
        expectSameSurfaces(compressed, *original);
        expectRendersLike(*reference, compressed, name);

        Scene broken = compressed;
        for (TriangleUvs& uv : broken.surface.uv0) {
            for (glm::vec2* corner : {&uv.uv0, &uv.uv1, &uv.uv2}) {
                corner->x += 1.0f / kCheckerCells;
            }
        }
        expectControlCaught(*reference, broken, "the copy with its UVs a checker cell off");
        EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
    }

    static Document* originalDocument;
    static Scene* original;
    static Reference* reference;
};

Document* CompressedCopies::originalDocument = nullptr;
Scene* CompressedCopies::original = nullptr;
Reference* CompressedCopies::reference = nullptr;

TEST_F(CompressedCopies, DracoRendersLikeTheOriginal) {
    expectCopyRendersLikeTheOriginal(MeshCodec::Draco, "draco");
}

TEST_F(CompressedCopies, MeshoptRendersLikeTheOriginal) {
    expectCopyRendersLikeTheOriginal(MeshCodec::Meshopt, "meshopt");
}

} // namespace
} // namespace wf::test
