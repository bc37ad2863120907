// glTF loader: the shipped Cornell box, then small files written here, each breaking or
// exercising one rule (transforms, index types, strides, bounds checks, file access, winding).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "errors.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/gltf_primitives.h"
#include "scene/gltf/gltf_scene_limits.h"
#include "scene/scene_summary.h"
#include "mini_gltf.h"

namespace wf {
namespace {

namespace fs = std::filesystem;
using test::base64;
using test::F32;
using test::MiniGltf;
using test::TempDir;
using test::U16;
using test::U32;
using test::U8;
using test::writeBytes;

const std::vector<float> TRIANGLE = {0, 0, 0, 1, 0, 0, 0, 1, 0};

// One triangle in mesh 0 under node 0 with the given extra node members.
MiniGltf oneTriangle(const std::string& nodeMembers = "") {
    MiniGltf g;
    g.addMesh(g.addPositions(TRIANGLE));
    g.nodes.push_back("{\"mesh\":0" + nodeMembers + "}");
    return g;
}

// The InputError message loading `path` gives; fails the test if there is none.
std::string inputError(const std::string& path) {
    try {
        loadGltf(path);
    } catch (const InputError& e) {
        std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        return message;
    }
    ADD_FAILURE() << "no InputError for " << path;
    return "";
}

void expectNear(const glm::vec3& actual, const glm::vec3& expected) {
    EXPECT_NEAR(actual.x, expected.x, 1e-5f);
    EXPECT_NEAR(actual.y, expected.y, 1e-5f);
    EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

glm::vec3 unitNormal(const Triangle& t) {
    return glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
}

TEST(GltfLoader, CornellBox) {
    Scene scene = loadGltf(std::string(WF_TEST_SCENE_DIR) + "/cornell_box.gltf");
    EXPECT_EQ(scene.triangles.size(), 32u); // 5 walls, light, 2 blocks of 5 faces; 2 each
    ASSERT_TRUE(scene.hasCamera);
    expectNear(scene.camera.forward, {0, 0, 1});
    expectNear(scene.camera.up, {0, 1, 0});
    EXPECT_NEAR(scene.camera.yfov, 0.686f, 0.01f);
    EXPECT_FLOAT_EQ(scene.camera.aspect, 1.0f);
    SceneSummary summary = summarize(scene);
    EXPECT_EQ(summary.emissiveTriangleCount, 2u);
    expectNear(summary.boundsLo, {0, 0, 0});
    expectNear(summary.boundsHi, {5.55f, 5.55f, 5.55f});
    for (const Triangle& t : scene.triangles) {
        for (const glm::vec3& p : {t.p0, t.p1, t.p2}) {
            EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
        }
        ASSERT_LT(t.material, scene.materials.size());
        EXPECT_EQ(t.emitter, WF_NO_EMITTER);
        const glm::vec3 emission = scene.materials[t.material].emission;
        if (emission.x > 0) {
            EXPECT_NEAR(emission.x, 17.0f, 1e-4f);
            EXPECT_LT(unitNormal(t).y, -0.99f); // the light faces down, into the box
        }
    }
    EXPECT_NE(describe(summary).find("32 triangles"), std::string::npos);
}

TEST(GltfLoader, TrsIsTranslateRotateScale) {
    TempDir dir;
    // Scale 2, then 90 degrees about +Z, then move by (1, 2, 3).
    const float h = std::sqrt(0.5f);
    MiniGltf g = oneTriangle(",\"translation\":[1,2,3],\"rotation\":[0,0," + std::to_string(h) +
                             "," + std::to_string(h) + "],\"scale\":[2,2,2]");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p0, {1, 2, 3});
    expectNear(scene.triangles[0].p1, {1, 4, 3});
    expectNear(scene.triangles[0].p2, {-1, 2, 3});
}

TEST(GltfLoader, MatrixIsColumnMajor) {
    TempDir dir;
    MiniGltf g = oneTriangle(",\"matrix\":[0,2,0,0, -2,0,0,0, 0,0,2,0, 1,2,3,1]");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p1, {1, 4, 3});
    expectNear(scene.triangles[0].p2, {-1, 2, 3});
}

TEST(GltfLoader, ChildTransformAppliesAfterParent) {
    TempDir dir;
    MiniGltf g = oneTriangle(",\"scale\":[2,2,2]");
    g.nodes.push_back(R"({"translation":[10,0,0],"children":[0]})");
    g.scenes = R"([{"nodes":[1]}])";
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p1, {12, 0, 0});
}

TEST(GltfLoader, WithoutScenesAllRootNodesLoad) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.nodes.push_back(R"({"mesh":0,"translation":[0,0,5]})");
    g.scenes = "[]";
    EXPECT_EQ(loadGltf(g.write(dir)).triangles.size(), 2u);
}

template <class T> void checkQuadWithIndices(int componentType) {
    TempDir dir;
    MiniGltf g;
    const int positions = g.addPositions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
    g.addMesh(positions, g.addIndices(std::vector<T>{0, 1, 2, 0, 2, 3}, componentType));
    g.nodes.push_back(R"({"mesh":0})");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 2u);
    expectNear(scene.triangles[1].p0, {0, 0, 0});
    expectNear(scene.triangles[1].p1, {1, 1, 0});
    expectNear(scene.triangles[1].p2, {0, 1, 0});
}

TEST(GltfLoader, IndicesU8) { checkQuadWithIndices<uint8_t>(U8); }
TEST(GltfLoader, IndicesU16) { checkQuadWithIndices<uint16_t>(U16); }
TEST(GltfLoader, IndicesU32) { checkQuadWithIndices<uint32_t>(U32); }

TEST(GltfLoader, NonIndexedTakesVerticesInOrder) {
    TempDir dir;
    MiniGltf g;
    g.addMesh(g.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0}));
    g.nodes.push_back(R"({"mesh":0})");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 2u);
    expectNear(scene.triangles[1].p1, {6, 0, 0});
}

TEST(GltfLoader, ByteStrideSkipsInterleavedData) {
    TempDir dir;
    MiniGltf g;
    const float nan = std::nanf("");
    // Position, then three floats of another attribute that must never be read as one.
    const std::vector<float> interleaved = {0, 0, 0, nan, nan, nan, 1, 0, 0, nan, nan, nan,
                                            0, 1, 0, nan, nan, nan};
    int view = g.addView(interleaved.data(), interleaved.size() * sizeof(float), 24);
    g.addMesh(g.addAccessor(view, F32, 3, "VEC3"));
    g.nodes.push_back(R"({"mesh":0})");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p2, {0, 1, 0});
}

TEST(GltfLoader, IndexPastVertexCountIsRejected) {
    TempDir dir;
    MiniGltf g;
    const int positions = g.addPositions(TRIANGLE);
    g.addMesh(positions, g.addIndices(std::vector<uint16_t>{0, 1, 3}, U16));
    g.nodes.push_back(R"({"mesh":0})");
    EXPECT_NE(inputError(g.write(dir)).find("is 3, but there are only 3 vertices"),
              std::string::npos);
}

TEST(GltfLoader, AccessorPastBufferViewIsRejected) {
    TempDir dir;
    MiniGltf g;
    int view = g.addView(TRIANGLE.data(), TRIANGLE.size() * sizeof(float));
    g.addMesh(g.addAccessor(view, F32, 3, "VEC3", 4)); // 4 bytes in, 4 bytes too long
    g.nodes.push_back(R"({"mesh":0})");
    EXPECT_NE(inputError(g.write(dir)).find("accessor 0"), std::string::npos);
}

TEST(GltfLoader, BufferViewPastBufferIsRejected) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.views[0] = R"({"buffer":0,"byteOffset":8,"byteLength":36})";
    EXPECT_NE(inputError(g.write(dir)).find("bufferView 0"), std::string::npos);
}

TEST(GltfLoader, BufferOutsideTheFolderIsRefused) {
    TempDir dir;
    fs::create_directories(dir.file("sub"));
    MiniGltf g = oneTriangle();
    writeBytes(dir.file("secret.bin"), g.bin); // exists and is valid: only the path is wrong
    g.bufferUri = "../secret.bin";
    const std::string path = dir.file("sub/scene.gltf");
    std::ofstream(path) << g.json();
    const std::string message = inputError(path);
    EXPECT_NE(message.find("../secret.bin"), std::string::npos) << message;
    EXPECT_NE(message.find("'..' is not allowed"), std::string::npos) << message;
}

TEST(GltfLoader, SymbolicLinkOutOfTheFolderIsRefused) {
    TempDir dir;
    fs::create_directories(dir.file("sub"));
    MiniGltf g = oneTriangle();
    writeBytes(dir.file("secret.bin"), g.bin);
    fs::create_symlink("../secret.bin", dir.file("sub/link.bin"));
    g.bufferUri = "link.bin";
    const std::string path = dir.file("sub/scene.gltf");
    std::ofstream(path) << g.json();
    EXPECT_NE(inputError(path).find("outside the scene's folder"), std::string::npos);
}

TEST(GltfLoader, AbsoluteBufferPathIsRefused) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    writeBytes(dir.file("data.bin"), g.bin);
    g.bufferUri = dir.file("data.bin");
    EXPECT_NE(inputError(g.write(dir)).find("only paths relative"), std::string::npos);
}

TEST(GltfLoader, BufferFileBesideTheSceneLoads) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.bufferUri = "data.bin";
    EXPECT_EQ(loadGltf(g.write(dir)).triangles.size(), 1u);
}

TEST(GltfLoader, MissingBufferFileIsNamed) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.bufferUri = "missing.bin";
    const std::string path = dir.file("scene.gltf");
    std::ofstream(path) << g.json(); // and no missing.bin
    EXPECT_NE(inputError(path).find("missing.bin"), std::string::npos);
}

TEST(GltfLoader, GlbLoads) {
    TempDir dir;
    MiniGltf g = oneTriangle(",\"translation\":[0,0,-1]");
    Scene scene = loadGltf(g.writeGlb(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p1, {1, 0, -1});
}

TEST(GltfLoader, NanPositionNamesTheAccessor) {
    TempDir dir;
    MiniGltf g;
    g.addPositions(TRIANGLE); // accessor 0, unused
    g.addMesh(g.addPositions({0, 0, 0, 1, std::nanf(""), 0, 0, 1, 0}));
    g.nodes.push_back(R"({"mesh":0})");
    const std::string message = inputError(g.write(dir));
    EXPECT_NE(message.find("accessor 1"), std::string::npos) << message;
    EXPECT_NE(message.find("element 1"), std::string::npos) << message;
}

TEST(GltfLoader, DegenerateTrianglesAreDropped) {
    TempDir dir;
    MiniGltf g;
    g.addMesh(g.addPositions({0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0}));
    g.nodes.push_back(R"({"mesh":0})");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p2, {0, 1, 0});
    // A zero scale makes every triangle degenerate after the transform.
    EXPECT_TRUE(loadGltf(oneTriangle(",\"scale\":[1,0,1]").write(dir)).triangles.empty());
}

TEST(GltfLoader, NodeCycleIsRejected) {
    TempDir dir;
    MiniGltf g = oneTriangle(",\"children\":[1]");
    g.nodes.push_back(R"({"children":[0]})");
    EXPECT_NE(inputError(g.write(dir)).find("cycle"), std::string::npos);
}

TEST(GltfLoader, NodeWithTwoParentsIsRejected) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.nodes.push_back(R"({"children":[0]})");
    g.nodes.push_back(R"({"children":[0]})");
    g.scenes = R"([{"nodes":[1,2]}])";
    EXPECT_NE(inputError(g.write(dir)).find("two parents"), std::string::npos);
}

TEST(GltfLoader, MirroringNodeKeepsTheFrontFace) {
    TempDir dir;
    MiniGltf g;
    g.addMesh(g.addPositions({1, 0, 0, 0, 1, 0, 0, 0, 1})); // front face towards (1, 1, 1)
    g.nodes.push_back(R"({"mesh":0,"scale":[-1,1,1]})");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.triangles.size(), 1u);
    // The mirror image of a surface facing (1, 1, 1) faces (-1, 1, 1).
    expectNear(unitNormal(scene.triangles[0]), glm::normalize(glm::vec3(-1, 1, 1)));
}

TEST(GltfLoader, MaterialsAndEmissiveStrength) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.meshes[0] = R"({"primitives":[{"attributes":{"POSITION":0},"material":0},
                                    {"attributes":{"POSITION":0}}]})";
    g.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.25,0.125,1]},
        "emissiveFactor":[1,0.5,0.25],"doubleSided":true,
        "extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":4}}})");
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.materials.size(), 2u); // the file's, then the default for primitive 1
    expectNear(scene.materials[0].emission, {4, 2, 1});
    expectNear(glm::vec3(scene.materials[0].baseColor), {0.5f, 0.25f, 0.125f});
    EXPECT_EQ(scene.materials[0].flags, WF_MATERIAL_DOUBLE_SIDED);
    expectNear(glm::vec3(scene.materials[1].baseColor), {0.8f, 0.8f, 0.8f});
    expectNear(scene.materials[1].emission, {0, 0, 0});
    ASSERT_EQ(scene.triangles.size(), 2u);
    EXPECT_EQ(scene.triangles[0].material, 0u);
    EXPECT_EQ(scene.triangles[1].material, 1u);
    EXPECT_EQ(scene.triangles[1].pad, 0u);
}

TEST(GltfLoader, DefaultMaterialAppendedOnce) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.nodes.push_back(R"({"mesh":0})");
    g.scenes = R"([{"nodes":[0,1]}])";
    Scene scene = loadGltf(g.write(dir));
    ASSERT_EQ(scene.materials.size(), 1u);
    EXPECT_EQ(scene.triangles.size(), 2u);
}

TEST(GltfLoader, MaterialIndexOutOfRangeIsRejected) {
    TempDir dir;
    MiniGltf g;
    g.addMesh(g.addPositions(TRIANGLE), -1, 3);
    g.nodes.push_back(R"({"mesh":0})");
    EXPECT_NE(inputError(g.write(dir)).find("material 3"), std::string::npos);
}

TEST(GltfLoader, NonTriangleModesAreSkipped) {
    TempDir dir;
    MiniGltf g;
    g.addMesh(g.addPositions(TRIANGLE), -1, -1, 1); // LINES
    g.nodes.push_back(R"({"mesh":0})");
    EXPECT_TRUE(loadGltf(g.write(dir)).triangles.empty());
}

TEST(GltfLoader, FirstCameraIsUsedOrthographicOrPerspective) {
    TempDir dir;
    MiniGltf g = oneTriangle();
    g.cameras.push_back(R"({"type":"orthographic","orthographic":{"xmag":1,"ymag":1,
                            "znear":0.1,"zfar":10}})");
    g.cameras.push_back(R"({"type":"perspective","perspective":{"yfov":0.5,"znear":0.1}})");
    // Node 1: orthographic (the first, so the default). Node 2: turned 90 degrees about +Y, so
    // it looks to -X.
    g.nodes.push_back(R"({"camera":0})");
    g.nodes.push_back(R"({"camera":1,"translation":[1,2,3],
                          "rotation":[0,0.70710678,0,0.70710678]})");
    g.scenes = R"([{"nodes":[0,1,2]}])";
    Scene scene = loadGltf(g.write(dir));
    ASSERT_TRUE(scene.hasCamera);
    ASSERT_EQ(scene.cameras.size(), 2u);
    EXPECT_FLOAT_EQ(scene.camera.orthoHalfHeight, 1.0f);
    EXPECT_FLOAT_EQ(scene.camera.aspect, 1.0f);
    const Camera& perspective = scene.cameras[1];
    expectNear(perspective.position, {1, 2, 3});
    expectNear(perspective.forward, {-1, 0, 0});
    expectNear(perspective.up, {0, 1, 0});
    EXPECT_FLOAT_EQ(perspective.yfov, 0.5f);
    EXPECT_EQ(perspective.aspect, 0.0f);
    EXPECT_EQ(perspective.orthoHalfHeight, 0.0f);
}

TEST(GltfLoader, UnreadableOrWrongFilesAreInputErrors) {
    TempDir dir;
    inputError(dir.file("absent.gltf"));
    std::ofstream(dir.file("broken.gltf")) << "{ not json";
    inputError(dir.file("broken.gltf"));
    std::ofstream(dir.file("text.glb")) << "{\"asset\":{\"version\":\"2.0\"}}";
    inputError(dir.file("text.glb"));
    EXPECT_THROW(loadGltf(dir.file("scene.obj")), InputError);
    // Deep nesting would overflow tinygltf's recursive JSON parser: refused before parsing.
    std::ofstream(dir.file("deep.gltf"))
        << "{\"asset\":{\"version\":\"2.0\"},\"extras\":" << std::string(100000, '[')
        << std::string(100000, ']') << "}";
    EXPECT_NE(inputError(dir.file("deep.gltf")).find("nested"), std::string::npos);
}

} // namespace
} // namespace wf

namespace wf {
namespace {

// A small file that places one 1000-triangle mesh at more nodes than memory can flatten is
// refused at once when flattened (--instancing off), from the accessors' counts, naming the
// limit, before any triangle is read; instanced (the default), it loads as 1000 triangles.
TEST(GltfLoader, PlacingAMeshPastTheTriangleLimitIsRefusedUpFront) {
    TempDir dir;
    MiniGltf g;
    std::vector<float> xyz;
    for (int t = 0; t < 1000; ++t)
        for (float v : {0.0f, 0.0f, float(t), 1.0f, 0.0f, float(t), 0.0f, 1.0f, float(t)})
            xyz.push_back(v);
    g.addMesh(g.addPositions(xyz));
    const std::size_t nodes = gltf::maxSceneTriangles() / 1000 + 1;
    std::string roots;
    for (std::size_t i = 0; i < nodes; ++i) {
        g.nodes.push_back("{\"mesh\":0}");
        roots += (i ? "," : "") + std::to_string(i);
    }
    g.scenes = "[{\"nodes\":[" + roots + "]}]";
    const std::string path = g.write(dir);
    const Scene instanced = loadGltf(path);
    EXPECT_EQ(instanced.triangles.size(), 1000u);
    EXPECT_EQ(instanced.placements.size(), nodes);
    try {
        GltfOptions flatten;
        flatten.instancing = Instancing::Off;
        loadGltf(path, nullptr, flatten);
        FAIL() << "a scene of " << nodes * 1000 << " triangles loaded";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(std::to_string(gltf::maxSceneTriangles())), std::string::npos)
            << message;
        EXPECT_NE(message.find(gltf::sceneTriangleLimitReason()), std::string::npos) << message;
    }
}

} // namespace
} // namespace wf
