// EXT_mesh_gpu_instancing (issue 48): a node's instance transforms load into exactly the
// triangles (flattened) and placements (instanced) that one child node per instance gives,
// attributes left out are the identity, integer quaternions decode as the spec says, and
// malformed instance attributes are refused in one line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "gpu_instanced_scene.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {
namespace {

using test::GpuInstancingCase;
using test::TempDir;

Scene load(const std::string& path, Instancing mode, std::vector<std::string>* warnings = nullptr,
           double shutter = 0.0) {
    GltfOptions options;
    options.instancing = mode;
    options.time = 0.25;
    if (shutter > 0.0) {
        options.shutterOpen = options.time - shutter;
        options.shutterClose = options.time + shutter;
        options.motionSegments = 2;
    }
    std::vector<std::string> ignored;
    return loadGltf(path, warnings ? warnings : &ignored, options);
}

// The two forms of `c`, loaded the same way, give the same scene, bit for bit.
void expectSameScenes(const GpuInstancingCase& c, Instancing mode, double shutter = 0.0) {
    TempDir dir;
    const Scene gpu = load(test::gpuInstancingScene(c, true).g.write(dir, "gpu.gltf"), mode,
                           nullptr, shutter);
    const Scene nodes = load(test::gpuInstancingScene(c, false).g.write(dir, "nodes.gltf"), mode,
                             nullptr, shutter);
    ASSERT_FALSE(nodes.triangles.empty());
    ASSERT_EQ(gpu.triangles.size(), nodes.triangles.size());
    for (std::size_t i = 0; i < gpu.triangles.size(); ++i) {
        const Triangle &a = gpu.triangles[i], &b = nodes.triangles[i];
        ASSERT_TRUE(a.p0 == b.p0 && a.p1 == b.p1 && a.p2 == b.p2 && a.material == b.material)
            << "triangle " << i;
    }
    ASSERT_EQ(gpu.surface.normals.size(), nodes.surface.normals.size());
    for (std::size_t i = 0; i < gpu.surface.normals.size(); ++i)
        ASSERT_TRUE(gpu.surface.normals[i].n0 == nodes.surface.normals[i].n0 &&
                    gpu.surface.normals[i].n1 == nodes.surface.normals[i].n1 &&
                    gpu.surface.normals[i].n2 == nodes.surface.normals[i].n2)
            << "normals of triangle " << i;
    ASSERT_EQ(gpu.meshes.size(), nodes.meshes.size());
    ASSERT_EQ(gpu.placements.size(), nodes.placements.size());
    for (std::size_t i = 0; i < gpu.placements.size(); ++i) {
        EXPECT_TRUE(gpu.placements[i].worldFromObject == nodes.placements[i].worldFromObject)
            << "placement " << i;
        EXPECT_EQ(gpu.placements[i].mesh, nodes.placements[i].mesh);
        EXPECT_TRUE(gpu.placements[i].motion == nodes.placements[i].motion) << "placement " << i;
    }
    EXPECT_EQ(gpu.motionSegments, nodes.motionSegments);
}

TEST(GltfGpuInstancing, FlattenedInstancesEqualOneNodePerInstance) {
    const GpuInstancingCase c = test::gpuInstancingCase(5);
    expectSameScenes(c, Instancing::Off);
    TempDir dir;
    const Scene one = load(test::gpuInstancingScene(test::gpuInstancingCase(1), true)
                               .g.write(dir, "one.gltf"), Instancing::Off);
    const Scene five = load(test::gpuInstancingScene(c, true).g.write(dir), Instancing::Off);
    EXPECT_TRUE(five.meshes.empty());
    EXPECT_EQ(five.triangles.size(), 5 * one.triangles.size()); // the node's own copy is not drawn
}

TEST(GltfGpuInstancing, InstancedPlacementsEqualOneNodePerInstance) {
    const GpuInstancingCase c = test::gpuInstancingCase(5);
    expectSameScenes(c, Instancing::On);
    TempDir dir;
    const Scene scene = load(test::gpuInstancingScene(c, true).g.write(dir), Instancing::On);
    ASSERT_EQ(scene.meshes.size(), 1u);
    EXPECT_EQ(scene.placements.size(), 5u);
    // Auto decides as it does for nodes: this small blob is flattened.
    EXPECT_TRUE(load(test::gpuInstancingScene(c, true).g.write(dir), Instancing::Auto)
                    .meshes.empty());
}

// The node's animation moves its instances, at the time and keyed over a shutter.
TEST(GltfGpuInstancing, AnimatedNodeMovesItsInstances) {
    GpuInstancingCase c = test::gpuInstancingCase(3);
    c.animated = true;
    expectSameScenes(c, Instancing::Off);
    expectSameScenes(c, Instancing::On, 0.1);
    TempDir dir;
    const Scene blurred =
        load(test::gpuInstancingScene(c, true).g.write(dir), Instancing::Off, nullptr, 0.1);
    ASSERT_EQ(blurred.placements.size(), 3u); // moving, so instanced and keyed
    EXPECT_EQ(blurred.placements[0].motion.size(), 3u);
    const GpuInstancingCase still = test::gpuInstancingCase(3);
    const Scene atRest = load(test::gpuInstancingScene(still, true).g.write(dir, "still.gltf"),
                              Instancing::On);
    EXPECT_FALSE(atRest.placements[0].worldFromObject == blurred.placements[0].worldFromObject);
}

TEST(GltfGpuInstancing, EmissiveInstancesAreFlattenedLights) {
    GpuInstancingCase c = test::gpuInstancingCase(4);
    c.material = R"({"emissiveFactor":[1,0.5,0.25]})";
    expectSameScenes(c, Instancing::On);
    TempDir dir;
    const Scene scene = load(test::gpuInstancingScene(c, true).g.write(dir), Instancing::On);
    EXPECT_TRUE(scene.meshes.empty());
    EXPECT_TRUE(scene.placements.empty());
    EXPECT_EQ(scene.materials[scene.triangles.back().material].emission, glm::vec3(1, 0.5, 0.25));
}

// Each attribute left out is the identity: the node form then has no such member either.
TEST(GltfGpuInstancing, MissingAttributesAreTheIdentity) {
    const GpuInstancingCase full = test::gpuInstancingCase(4);
    for (int subset = 1; subset < 8; ++subset) {
        GpuInstancingCase c = full;
        if (!(subset & 1))
            c.translation.clear();
        if (!(subset & 2))
            c.rotation.clear();
        if (!(subset & 4))
            c.scale.clear();
        SCOPED_TRACE("subset " + std::to_string(subset));
        expectSameScenes(c, Instancing::On);
        expectSameScenes(c, Instancing::Off);
    }
    // Only TRANSLATION: the instances are the node's placement moved, nothing else.
    GpuInstancingCase c = full;
    c.rotation.clear();
    c.scale.clear();
    TempDir dir;
    const Scene moved = load(test::gpuInstancingScene(c, true).g.write(dir), Instancing::On);
    for (std::size_t i = 1; i < moved.placements.size(); ++i)
        EXPECT_TRUE(glm::mat3(moved.placements[i].worldFromObject) ==
                    glm::mat3(moved.placements[0].worldFromObject));
}

// BYTE normalized: c / 127, SHORT normalized: c / 32767, the most negative value clamped to
// -1; the quaternion is then renormalised as node rotations are.
TEST(GltfGpuInstancing, NormalizedIntegerQuaternionsDecodeAsTheSpecSays) {
    for (const int type : {test::I8, test::I16}) {
        const int one = type == test::I8 ? 127 : 32767, lowest = type == test::I8 ? -128 : -32768;
        GpuInstancingCase c = test::gpuInstancingCase(4);
        c.rotationType = type;
        c.rotationInts = {0, one, 0, 0,                 // 180 degrees about y
                          lowest, 0, 0, 0,              // -1 after the clamp: 180 about x
                          0, 0, one / 2 + 1, one / 2 + 1, // 90 about z, not unit until renormalised
                          one / 3, -one / 5, one / 7, one * 9 / 10};
        c.rotation.clear();
        for (int v : c.rotationInts)
            c.rotation.push_back(std::max(float(v) / float(one), -1.0f));
        SCOPED_TRACE(type == test::I8 ? "BYTE" : "SHORT");
        expectSameScenes(c, Instancing::On);
        // Against the geometry itself: with nothing else set, instance 1 turns the blob half a
        // turn about x, so its placement is the node's times diag(1, -1, -1).
        GpuInstancingCase bare = c;
        bare.translation.clear();
        bare.scale.clear();
        TempDir dir;
        const Scene scene = load(test::gpuInstancingScene(bare, true).g.write(dir), Instancing::On);
        ASSERT_EQ(scene.placements.size(), 4u);
        const glm::mat3 node = glm::mat3(scene.placements[1].worldFromObject) *
                               glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, -1, 0),
                                         glm::vec3(0, 0, -1));
        // placements[1] = node x Rx(180), so placements[1] x Rx(180) is the node, as is
        // placements[0] x Ry(180).
        const glm::mat3 node0 = glm::mat3(scene.placements[0].worldFromObject) *
                                glm::mat3(glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                                          glm::vec3(0, 0, -1));
        for (int col = 0; col < 3; ++col)
            for (int row = 0; row < 3; ++row)
                EXPECT_NEAR(node[col][row], node0[col][row], 1e-5f);
    }
}

std::string refusal(const test::MiniGltf& g, const TempDir& dir) {
    try {
        load(g.write(dir, "bad.gltf"), Instancing::Auto);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(loaded)";
}

void expectRefused(const test::MiniGltf& g, const std::string& says) {
    TempDir dir;
    const std::string message = refusal(g, dir);
    EXPECT_NE(message.find(says), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(GltfGpuInstancing, MalformedAttributesAreRefusedInOneLine) {
    const GpuInstancingCase c = test::gpuInstancingCase(3);
    auto file = [&] { return test::gpuInstancingScene(c, true); };
    {
        test::GpuInstancingFile f = file(); // SCALE says 2 instances, the others 3
        std::string& s = f.g.accessors[f.scale];
        s.replace(s.find("\"count\":3"), 9, "\"count\":2");
        expectRefused(f.g, "attributes differ in count (ROTATION has 3, SCALE 2)");
    }
    {
        test::GpuInstancingFile f = file(); // the application's attributes are counted too
        std::string& node = f.g.nodes[1];
        node.insert(node.find("\"TRANSLATION\""), "\"_ID\":0,");
        expectRefused(f.g, "attributes differ in count (ROTATION has 3, _ID ");
    }
    {
        test::GpuInstancingFile f = file();
        std::string& t = f.g.accessors[f.translation];
        t.replace(t.find("VEC3"), 4, "VEC4");
        expectRefused(f.g, "TRANSLATION (accessor " + std::to_string(f.translation) +
                               ") must be VEC3 of FLOAT");
    }
    {
        test::GpuInstancingFile f = file(); // SCALE as non-float: only ROTATION may be integers
        std::string& s = f.g.accessors[f.scale];
        s.replace(s.find("5126"), 4, "5122");
        expectRefused(f.g, "SCALE (accessor " + std::to_string(f.scale) + ") must be VEC3");
    }
    {
        GpuInstancingCase u = c; // unsigned and unnormalized rotations are not in the spec
        u.rotationType = test::I16;
        u.rotationInts.assign(12, 100);
        test::GpuInstancingFile f = test::gpuInstancingScene(u, true);
        std::string unsignedShort = f.g.accessors[f.rotation];
        unsignedShort.replace(unsignedShort.find("5122"), 4, "5123");
        std::string unnormalized = f.g.accessors[f.rotation];
        unnormalized.replace(unnormalized.find("\"normalized\":true"), 17, "\"normalized\":false");
        f.g.accessors[f.rotation] = unsignedShort;
        expectRefused(f.g, "ROTATION (accessor " + std::to_string(f.rotation) +
                               ") must be VEC4 of FLOAT, or of normalized BYTE or SHORT");
        f.g.accessors[f.rotation] = unnormalized;
        expectRefused(f.g, "must be VEC4 of FLOAT, or of normalized BYTE or SHORT");
    }
    {
        GpuInstancingCase bad = c; // non-finite values, as NaN positions are
        bad.translation[4] = std::nanf("");
        expectRefused(test::gpuInstancingScene(bad, true).g, "has a NaN or infinite value in element 1");
        bad = c;
        bad.scale[8] = INFINITY;
        expectRefused(test::gpuInstancingScene(bad, true).g, "has a NaN or infinite value in element 2");
        bad = c;
        std::fill(bad.rotation.begin() + 8, bad.rotation.end(), 0.0f);
        expectRefused(test::gpuInstancingScene(bad, true).g,
                      "instance 2: ROTATION is not a usable quaternion");
    }
    {
        test::GpuInstancingFile f = file();
        std::string& node = f.g.nodes[1];
        node.replace(node.find("\"SCALE\":"), 8 + std::to_string(f.scale).size(), "\"SCALE\":99");
        expectRefused(f.g, "SCALE refers to an accessor that does not exist");
    }
    {
        test::GpuInstancingFile f = file();
        std::string& node = f.g.nodes[1];
        node.replace(node.find("{\"attributes\""), 13, "{\"attributez\"");
        expectRefused(f.g, "EXT_mesh_gpu_instancing needs an \"attributes\" object");
    }
    {
        test::GpuInstancingFile f = file(); // a huge count, refused before anything is read
        for (int a : {f.translation, f.rotation, f.scale}) {
            std::string& s = f.g.accessors[a];
            s.replace(s.find("\"count\":3"), 9, "\"count\":16777217");
        }
        expectRefused(f.g, "places 16777217 instances; 1 to 16777216 are allowed");
    }
}

TEST(GltfGpuInstancing, ReadWithoutTheIgnoringWarning) {
    TempDir dir;
    test::GpuInstancingFile f = test::gpuInstancingScene(test::gpuInstancingCase(2), true);
    f.g.extra = R"(,"extensionsUsed":["EXT_mesh_gpu_instancing"],)"
                R"("extensionsRequired":["EXT_mesh_gpu_instancing"])";
    std::string& node = f.g.nodes[1];
    const std::string two = std::to_string(f.translation); // an accessor of 2 elements
    node.insert(node.find("\"TRANSLATION\""), "\"_ID\":" + two + ",\"COLOR\":0,");
    std::vector<std::string> warnings;
    const Scene scene = load(f.g.write(dir), Instancing::On, &warnings);
    EXPECT_EQ(scene.placements.size(), 2u);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("ignoring EXT_mesh_gpu_instancing attribute COLOR"),
              std::string::npos) << warnings[0];
    for (const std::string& line : warnings)
        EXPECT_EQ(line.find("ignoring glTF extension"), std::string::npos) << line;
}

} // namespace
} // namespace wf
