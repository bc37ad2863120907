// Animation on the host against closed forms: each interpolation (STEP, LINEAR, CUBICSPLINE with
// tangents scaled by the interval), slerp's shorter arc, clamping outside the keys; then whole
// files: a two-bone skinned triangle posed at a time against the pose computed by hand, morph
// targets against their deltas, and broken animations refused in one line.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "errors.h"
#include "mini_gltf.h"
#include "scene/animation/deformation.h"
#include "scene/animation/keyframes.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {
namespace {

using anim::Interpolation;
using anim::Keyframes;

TEST(Keyframes, LinearInterpolatesAndClampsOutsideTheKeys) {
    Keyframes k{{1.0f, 3.0f}, {0, 0, 0, 2, 4, 6}, 3, Interpolation::Linear};
    const std::vector<double> mid = anim::sample(k, 2.0);
    EXPECT_DOUBLE_EQ(mid[0], 1.0);
    EXPECT_DOUBLE_EQ(mid[1], 2.0);
    EXPECT_DOUBLE_EQ(mid[2], 3.0);
    EXPECT_DOUBLE_EQ(anim::sample(k, 1.5)[1], 1.0);
    EXPECT_DOUBLE_EQ(anim::sample(k, -4.0)[2], 0.0); // before the first key: the first value
    EXPECT_DOUBLE_EQ(anim::sample(k, 9.0)[2], 6.0);  // after the last: the last
}

TEST(Keyframes, StepHoldsEachKeyUntilTheNext) {
    Keyframes k{{0.0f, 1.0f, 2.0f}, {5, 7, 9}, 1, Interpolation::Step};
    EXPECT_DOUBLE_EQ(anim::sample(k, 0.0)[0], 5.0);
    EXPECT_DOUBLE_EQ(anim::sample(k, 0.999)[0], 5.0);
    EXPECT_DOUBLE_EQ(anim::sample(k, 1.0)[0], 7.0);
    EXPECT_DOUBLE_EQ(anim::sample(k, 1.5)[0], 7.0);
    EXPECT_DOUBLE_EQ(anim::sample(k, 3.0)[0], 9.0);
}

// p(s) = h00 v0 + h10 dt m0 + h01 v1 + h11 dt m1 with dt = 2: at s = 1/2, 2*(1/8)*3 + 2/2 +
// 2*(-1/8)*(-1) = 2; its slope at the first key is the out-tangent itself (3 per second).
TEST(Keyframes, CubicSplineScalesTangentsByTheInterval) {
    Keyframes k{{0.0f, 2.0f}, {/*in*/ 0, /*v*/ 0, /*out*/ 3, /*in*/ -1, /*v*/ 2, /*out*/ 0}, 1,
                Interpolation::CubicSpline};
    EXPECT_NEAR(anim::sample(k, 1.0)[0], 2.0, 1e-12);
    const double h = 1e-6;
    EXPECT_NEAR((anim::sample(k, h)[0] - anim::sample(k, 0.0)[0]) / h, 3.0, 1e-4);
    EXPECT_NEAR((anim::sample(k, 2.0)[0] - anim::sample(k, 2.0 - h)[0]) / h, -1.0, 1e-4);
    EXPECT_DOUBLE_EQ(anim::sample(k, 5.0)[0], 2.0);
    // Sampled anywhere in the interval, the closed form of the Hermite cubic.
    for (double t : {0.3, 0.7, 1.4, 1.9}) {
        const double s = t / 2.0;
        const double expect = (s * s * s - 2 * s * s + s) * 2 * 3 + (-2 * s * s * s + 3 * s * s) * 2 +
                              (s * s * s - s * s) * 2 * -1;
        EXPECT_NEAR(anim::sample(k, t)[0], expect, 1e-12) << t;
    }
}

double angleAboutZ(const std::vector<double>& q) {
    return 2.0 * std::atan2(q[2] * (q[3] < 0 ? -1 : 1), std::abs(q[3]));
}

TEST(Keyframes, RotationSlerpsAlongTheShorterArcAtConstantSpeed) {
    const double half = M_PI / 4; // a 90-degree turn about z
    // The second key written as -q: the same rotation, whose plain lerp would take the long way.
    Keyframes k{{0.0f, 1.0f},
                {0, 0, 0, 1, 0, 0, -float(std::sin(half)), -float(std::cos(half))},
                4,
                Interpolation::Linear,
                true};
    for (double u : {0.25, 0.5, 0.75}) {
        const std::vector<double> q = anim::sample(k, u);
        EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
        EXPECT_NEAR(angleAboutZ(q), u * M_PI / 2, 1e-6) << u;
    }
    // Cubic rotations come out normalised too.
    Keyframes c{{0.0f, 1.0f}, {0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0},
                4, Interpolation::CubicSpline, true};
    const std::vector<double> q = anim::sample(c, 0.5);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1.0, 1e-12);
}

TEST(Deformation, MorphTargetsAddWeightedDeltas) {
    std::vector<float> values = {1, 2, 3};
    const float d0[] = {1, 0, 0}, d1[] = {0, 2, 0};
    anim::applyMorphTargets(values, {d0, nullptr, d1}, {0.5, 9.0, 0.25});
    EXPECT_FLOAT_EQ(values[0], 1.5f);
    EXPECT_FLOAT_EQ(values[1], 2.5f);
    EXPECT_FLOAT_EQ(values[2], 3.0f);
}

TEST(Deformation, SkinWeightsAreNormalised) {
    const std::vector<glm::dmat4> joints = {glm::dmat4(1.0),
                                            glm::translate(glm::dmat4(1.0), {2, 0, 0})};
    const float j[] = {0, 1, 0, 0}, w[] = {3, 1, 0, 0};
    EXPECT_DOUBLE_EQ(anim::skinMatrix(joints, j, w, 4)[3][0], 0.5);
    const float none[] = {0, 0, 0, 0};
    EXPECT_EQ(anim::skinMatrix(joints, j, none, 4), glm::dmat4(1.0));
}

// --- Whole files. ---

template <class T> int addData(test::MiniGltf& g, const std::vector<T>& v, int type, size_t count,
                               const std::string& kind) {
    return g.addAccessor(g.addView(v.data(), v.size() * sizeof(T)), type, count, kind);
}

// Two joints: node 1 at the origin, node 2 one unit up (its child), turned about z by an
// animation from 0 to 90 degrees over a second. The triangle's corners follow joint 0, both
// (weights 1 and 1, normalised to halves) and joint 1. The mesh's node moves by 5 in x, which
// glTF says a skinned mesh ignores.
test::MiniGltf twoBoneFile() {
    test::MiniGltf g;
    const int pos = g.addPositions({0, 0, 0, 1, 0, 0, 0.1f, 1.5f, 0});
    const int joints = addData<uint8_t>(g, {0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0}, test::U8, 3, "VEC4");
    const int weights = addData<float>(g, {1, 0, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0}, test::F32, 3, "VEC4");
    std::vector<float> ibm(32, 0.0f);
    for (int i = 0; i < 4; ++i)
        ibm[i * 5] = ibm[16 + i * 5] = 1.0f;
    ibm[16 + 13] = -1.0f; // joint 1 bound one unit up: its inverse moves down
    const int ibmAcc = addData<float>(g, ibm, test::F32, 2, "MAT4");
    const int times = addData<float>(g, {0, 1}, test::F32, 2, "SCALAR");
    const float s = float(std::sin(M_PI / 4)), c = float(std::cos(M_PI / 4));
    const int rotations = addData<float>(g, {0, 0, 0, 1, 0, 0, s, c}, test::F32, 2, "VEC4");
    g.addMesh(pos, -1, -1, 4,
              ",\"JOINTS_0\":" + std::to_string(joints) + ",\"WEIGHTS_0\":" + std::to_string(weights));
    g.nodes = {R"({"children":[1,3]})", R"({"children":[2]})", R"({"translation":[0,1,0]})",
               R"({"mesh":0,"skin":0,"translation":[5,0,0]})"};
    g.extra = ",\"skins\":[{\"joints\":[1,2],\"inverseBindMatrices\":" + std::to_string(ibmAcc) +
              "}],\"animations\":[{\"name\":\"bend\",\"channels\":[{\"sampler\":0,\"target\":{"
              "\"node\":2,\"path\":\"rotation\"}}],\"samplers\":[{\"input\":" +
              std::to_string(times) + ",\"output\":" + std::to_string(rotations) + "}]}]";
    return g;
}

void expectNear(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

TEST(GltfAnimation, TwoBoneSkinMatchesTheHandComputedPose) {
    test::TempDir dir;
    const std::string path = twoBoneFile().write(dir);
    for (double t : {0.0, 0.5, 1.0, 3.0}) {
        GltfOptions options;
        options.time = t;
        const Scene scene = loadGltf(path, nullptr, options);
        ASSERT_EQ(scene.triangles.size(), 1u);
        const double a = std::min(t, 1.0) * M_PI / 2; // joint 1's turn, clamped after 1 s
        // Joint 1's world is T(0,1,0) Rz(a); its inverse bind T(0,-1,0): a corner p on it moves
        // to (0,1,0) + Rz(a) (p - (0,1,0)).
        auto onJoint1 = [a](double x, double y) {
            return glm::vec3(float(x * std::cos(a) - (y - 1) * std::sin(a)),
                             float(1 + x * std::sin(a) + (y - 1) * std::cos(a)), 0.0f);
        };
        const Triangle& tri = scene.triangles[0];
        expectNear(tri.p0, glm::vec3(0, 0, 0));
        expectNear(tri.p1, 0.5f * glm::vec3(1, 0, 0) + 0.5f * onJoint1(1, 0));
        expectNear(tri.p2, onJoint1(0.1, 1.5));
    }
}

TEST(GltfAnimation, AnimationChoiceByNameOrIndex) {
    test::TempDir dir;
    const std::string path = twoBoneFile().write(dir);
    GltfOptions options;
    options.time = 1.0;
    options.animation = "bend";
    const float byName = loadGltf(path, nullptr, options).triangles[0].p2.x;
    options.animation = "0";
    EXPECT_EQ(loadGltf(path, nullptr, options).triangles[0].p2.x, byName);
    EXPECT_NEAR(byName, -0.5f, 1e-5f);
    options.animation = "walk";
    try {
        loadGltf(path, nullptr, options);
        FAIL() << "an unknown animation was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("no such animation (the file has 0 'bend')"),
                  std::string::npos)
            << e.what();
    }
}

// One triangle, two POSITION targets; mesh weights (0.5, 0) at rest, and a weights channel from
// (0, 0) to (1, 0.5) over two seconds.
test::MiniGltf morphFile(const std::string& interpolation = "LINEAR", size_t outputCount = 4,
                         int sampler = 0) {
    test::MiniGltf g;
    const int pos = g.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int d0 = g.addPositions({0, 0, 1, 0, 0, 1, 0, 0, 1});
    const int d1 = g.addPositions({2, 0, 0, 0, 0, 0, 0, 0, 0});
    const int times = addData<float>(g, {0, 2}, test::F32, 2, "SCALAR");
    const int w = addData<float>(g, {0, 0, 1, 0.5f}, test::F32, outputCount, "SCALAR");
    g.meshes.push_back("{\"primitives\":[{\"attributes\":{\"POSITION\":" + std::to_string(pos) +
                       "},\"targets\":[{\"POSITION\":" + std::to_string(d0) +
                       "},{\"POSITION\":" + std::to_string(d1) + "}]}],\"weights\":[0.5,0]}");
    g.nodes = {R"({"mesh":0})"};
    g.extra = ",\"animations\":[{\"channels\":[{\"sampler\":" + std::to_string(sampler) +
              ",\"target\":{\"node\":0,\"path\":\"weights\"}}],\"samplers\":[{\"input\":" +
              std::to_string(times) + ",\"output\":" + std::to_string(w) +
              ",\"interpolation\":\"" + interpolation + "\"}]}]";
    return g;
}

TEST(GltfAnimation, MorphTargetsFollowAnimatedWeights) {
    test::TempDir dir;
    GltfOptions options;
    options.time = 1.0; // weights (0.5, 0.25)
    const Scene scene = loadGltf(morphFile().write(dir), nullptr, options);
    ASSERT_EQ(scene.triangles.size(), 1u);
    expectNear(scene.triangles[0].p0, {0.5f, 0, 0.5f});
    expectNear(scene.triangles[0].p1, {1, 0, 0.5f});
    expectNear(scene.triangles[0].p2, {0, 1, 0.5f});
    // Without the animation, the mesh's own weights.
    test::MiniGltf still = morphFile();
    still.extra.clear();
    const Scene rest = loadGltf(still.write(dir, "still.gltf"));
    expectNear(rest.triangles[0].p0, {0, 0, 0.5f});
}

// Key times that do not increase (accessors without a bufferView give all zeros, and the
// validator calls such files valid): at time 0 with no animation named, the animation is dropped
// with one warning and the scene is at rest; any other time refuses the file.
TEST(GltfAnimation, UnorderedKeyTimesAreDroppedAtRestOnly) {
    test::TempDir dir;
    test::MiniGltf g = morphFile();
    const int times = addData<float>(g, {0, 0}, test::F32, 2, "SCALAR");
    g.extra.replace(g.extra.find("\"input\":") + 8, 1, std::to_string(times));
    const std::string path = g.write(dir);
    std::vector<std::string> warnings;
    const Scene rest = loadGltf(path, &warnings);
    ASSERT_EQ(rest.triangles.size(), 1u);
    expectNear(rest.triangles[0].p0, {0, 0, 0.5f}); // the mesh's own weights
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("animation 0 ignored"), std::string::npos) << warnings[0];
    GltfOptions options;
    options.time = 1.0;
    EXPECT_THROW(loadGltf(path, nullptr, options), InputError);
    options.time = 0.0;
    options.animation = "0";
    EXPECT_THROW(loadGltf(path, nullptr, options), InputError);
}

void expectRefused(const test::MiniGltf& g, const std::string& substring) {
    test::TempDir dir;
    try {
        loadGltf(g.write(dir));
        FAIL() << "accepted; expected a refusal with: " << substring;
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find(substring), std::string::npos) << what;
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
}

TEST(GltfAnimation, BrokenAnimationsAreRefusedInOneLine) {
    expectRefused(morphFile("LINEAR", 4, 3), "channel 0: sampler 3 does not exist");
    expectRefused(morphFile("LINEAR", 3), "output has 3 elements, but 2 keys of LINEAR for 2 "
                                          "morph targets need 4");
    expectRefused(morphFile("CUBICSPLINE", 4), "need 12");
    expectRefused(morphFile("SMOOTH", 4), "interpolation 'SMOOTH' is not LINEAR, STEP or CUBICSPLINE");
}

} // namespace
} // namespace wf
