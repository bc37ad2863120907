// A skinned file rendered at --time t against a static file that the test posed at t itself:
// the same image within noise (each 8x8 region within 5 standard errors). The arm is a square
// tube on two joints (the upper one turned about z by the animation); its rings below the
// elbow follow joint 0, the elbow ring both (weights 1 and 1, normalised to halves), those
// above joint 1, and its node carries a translation glTF says a skinned mesh ignores. The
// posed copy's corners come from the closed form of that turn, with no skin and no animation.
#include <gtest/gtest.h>

#include <cmath>

#include "gpu_test_util.h"
#include "mini_gltf.h"
#include "scene/gltf/gltf_loader.h"

namespace wf::test {
namespace {

constexpr float kHalf = 0.25f;
const float kRingY[] = {0.0f, 0.5f, 1.0f, 1.5f, 2.0f};

template <class T> int addData(MiniGltf& g, const std::vector<T>& v, int type, size_t count,
                               const std::string& kind) {
    return g.addAccessor(g.addView(v.data(), v.size() * sizeof(T)), type, count, kind);
}

// The tube's corners, ring by ring, each mapped by `pose(x, y, z, ring)`; indices close the
// sides and the top. A floor under it; a camera looking at it from +z.
template <class Pose> std::vector<float> tubeCorners(Pose pose) {
    std::vector<float> p;
    const float corners[4][2] = {{-kHalf, -kHalf}, {kHalf, -kHalf}, {kHalf, kHalf}, {-kHalf, kHalf}};
    for (int r = 0; r < 5; ++r)
        for (const auto& c : corners) {
            const glm::vec3 q = pose(c[0], kRingY[r], c[1], r);
            p.insert(p.end(), {q.x, q.y, q.z});
        }
    return p;
}

std::vector<uint16_t> tubeIndices() {
    std::vector<uint16_t> idx;
    for (uint16_t r = 0; r < 4; ++r)
        for (uint16_t k = 0; k < 4; ++k) {
            const uint16_t a = r * 4 + k, b = r * 4 + (k + 1) % 4;
            idx.insert(idx.end(), {a, b, uint16_t(b + 4), a, uint16_t(b + 4), uint16_t(a + 4)});
        }
    idx.insert(idx.end(), {16, 18, 17, 16, 19, 18});
    return idx;
}

void addFloorAndCamera(MiniGltf& g, std::vector<std::string>& sceneNodes) {
    const int floor = g.addPositions({-3, 0, -3, -3, 0, 3, 3, 0, 3, 3, 0, -3});
    const int floorIdx = g.addIndices<uint16_t>({0, 1, 2, 0, 2, 3}, U16);
    g.addMesh(floor, floorIdx);
    g.nodes.push_back("{\"mesh\":" + std::to_string(g.meshes.size() - 1) + "}");
    sceneNodes.push_back(std::to_string(g.nodes.size() - 1));
    g.cameras.push_back(R"({"type":"perspective","perspective":{"yfov":0.9,"aspectRatio":1.5,"znear":0.05}})");
    g.nodes.push_back(R"({"camera":0,"translation":[0,1.2,4.5]})");
    sceneNodes.push_back(std::to_string(g.nodes.size() - 1));
}

// Joint 1's turn at time t: 0 to 90 degrees over the first second, linear in angle (slerp).
double turnAt(double t) { return std::clamp(t, 0.0, 1.0) * M_PI / 2; }

std::string skinnedFile(const TempDir& dir) {
    MiniGltf g;
    const int pos = g.addPositions(tubeCorners([](float x, float y, float z, int) {
        return glm::vec3(x, y, z);
    }));
    std::vector<uint8_t> joints;
    std::vector<float> weights;
    for (int r = 0; r < 5; ++r)
        for (int k = 0; k < 4; ++k) {
            joints.insert(joints.end(), {0, 1, 0, 0});
            weights.insert(weights.end(), {r < 2 ? 1.0f : r == 2 ? 1.0f : 0.0f,
                                           r < 2 ? 0.0f : 1.0f, 0.0f, 0.0f});
        }
    const int j = addData<uint8_t>(g, joints, U8, 20, "VEC4");
    const int w = addData<float>(g, weights, F32, 20, "VEC4");
    std::vector<float> ibm(32, 0.0f);
    for (int i = 0; i < 4; ++i)
        ibm[i * 5] = ibm[16 + i * 5] = 1.0f;
    ibm[16 + 13] = -1.0f;
    const int ibmAcc = addData<float>(g, ibm, F32, 2, "MAT4");
    const int times = addData<float>(g, {0, 1}, F32, 2, "SCALAR");
    const float s = float(std::sin(M_PI / 4)), c = float(std::cos(M_PI / 4));
    const int rotations = addData<float>(g, {0, 0, 0, 1, 0, 0, s, c}, F32, 2, "VEC4");
    g.addMesh(pos, g.addIndices(tubeIndices(), U16), -1, 4,
              ",\"JOINTS_0\":" + std::to_string(j) + ",\"WEIGHTS_0\":" + std::to_string(w));
    g.nodes = {R"({"children":[1]})", R"({"translation":[0,1,0]})",
               R"({"mesh":0,"skin":0,"translation":[2,0,0]})"};
    std::vector<std::string> sceneNodes = {"0", "2"};
    addFloorAndCamera(g, sceneNodes);
    g.scenes = "[{\"nodes\":" + join(sceneNodes) + "}]";
    g.extra = ",\"skins\":[{\"joints\":[0,1],\"inverseBindMatrices\":" + std::to_string(ibmAcc) +
              "}],\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":1,\"path\":"
              "\"rotation\"}}],\"samplers\":[{\"input\":" + std::to_string(times) +
              ",\"output\":" + std::to_string(rotations) + "}]}]";
    return g.write(dir, "skinned.gltf");
}

// The same tube posed at t by hand: joint 1 maps p to (0,1,0) + Rz(a) (p - (0,1,0)).
std::string posedFile(const TempDir& dir, double t) {
    const double a = turnAt(t);
    auto onJoint1 = [a](float x, float y, float z) {
        return glm::vec3(float(x * std::cos(a) - (y - 1) * std::sin(a)),
                         float(1 + x * std::sin(a) + (y - 1) * std::cos(a)), z);
    };
    MiniGltf g;
    const int pos = g.addPositions(tubeCorners([&](float x, float y, float z, int ring) {
        if (ring < 2)
            return glm::vec3(x, y, z);
        if (ring == 2)
            return 0.5f * glm::vec3(x, y, z) + 0.5f * onJoint1(x, y, z);
        return onJoint1(x, y, z);
    }));
    g.addMesh(pos, g.addIndices(tubeIndices(), U16));
    g.nodes = {R"({"mesh":0})"};
    std::vector<std::string> sceneNodes = {"0"};
    addFloorAndCamera(g, sceneNodes);
    g.scenes = "[{\"nodes\":" + join(sceneNodes) + "}]";
    return g.write(dir, "posed.gltf");
}

TEST(AnimationRender, SkinnedAtTimeMatchesTheHandPosedStaticFile) {
    TempDir dir;
    const std::string skinned = skinnedFile(dir);
    const double t = 0.6;
    GltfOptions options;
    options.time = t;
    std::vector<std::string> warnings;
    const Scene animated = loadGltf(skinned, &warnings, options);
    const Scene posed = loadGltf(posedFile(dir, t), &warnings);
    ASSERT_EQ(animated.triangles.size(), posed.triangles.size());

    RenderSettings settings;
    settings.width = 48;
    settings.height = 32;
    settings.maxDepth = 3;
    settings.samplesPerPixel = 256;
    settings.aov = true; // the reference's variance per pixel
    settings.seed = 99;
    const RenderResult reference = renderScene(posed, settings);
    settings.aov = false;
    settings.samplesPerPixel = 64;
    std::vector<std::vector<float>> images;
    for (uint32_t seed = 1; seed <= 4; ++seed) {
        settings.seed = seed;
        images.push_back(renderScene(animated, settings).rgb);
    }
    const int checked = expectRegionsUnbiased(images, reference.rgb, reference.aov.variance,
                                              settings.width, settings.height, 8,
                                              "skinned at t=0.6 against hand-posed");
    EXPECT_EQ(checked, 24);
    // The pose matters: the rest pose differs from the posed file in some region.
    EXPECT_GT(imageMean(reference.rgb).mean, 0.05);
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace
} // namespace wf::test
