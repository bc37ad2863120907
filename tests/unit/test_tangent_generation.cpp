// MikkTSpace-compatible tangents against frames known in closed form: planes under any affine
// UV map, a cylinder and a sphere band (dP/du orthonormalised), a mirrored seam (handedness
// flips, sides not averaged), a UV seam (not joined), degenerate UVs and positions (finite, and
// taken from healthy neighbours as MikkTSpace does), and the loader's frames in world space.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <glm/geometric.hpp>
#include <glm/gtc/packing.hpp>
#include <glm/mat2x2.hpp>

#include "scene/gltf/gltf_loader.h"
#include "scene/gltf/tangent_generation.h"

namespace wf {
namespace {

constexpr float kPi = 3.14159265358979f;

struct Vertex {
    glm::vec3 p, n;
    glm::vec2 uv;
};

void addTriangle(TangentCorners& mesh, const Vertex& a, const Vertex& b, const Vertex& c) {
    for (const Vertex* v : {&a, &b, &c}) {
        mesh.positions.push_back(v->p);
        mesh.normals.push_back(v->n);
        mesh.uvs.push_back(v->uv);
    }
}

// A grid over (x, y) in [0, 1]^2 as quads (a, b, c), (a, c, d), counter-clockwise seen from the
// side the normal points to when the surface's x and y are dP/dx and dP/dy.
TangentCorners grid(int nx, int ny, const std::function<Vertex(float, float)>& at) {
    TangentCorners mesh;
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const float x0 = float(i) / nx, x1 = float(i + 1) / nx;
            const float y0 = float(j) / ny, y1 = float(j + 1) / ny;
            const Vertex a = at(x0, y0), b = at(x1, y0), c = at(x1, y1), d = at(x0, y1);
            addTriangle(mesh, a, b, c);
            addTriangle(mesh, a, c, d);
        }
    }
    return mesh;
}

// atan2 rather than acos: float acos cannot resolve angles under ~3e-4 near a dot of 1.
float angleBetween(const glm::vec3& a, const glm::vec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

void expectFrame(const glm::vec4& got, const glm::vec3& tangent, float w, float radians,
                 const std::string& where) {
    EXPECT_LT(angleBetween(glm::vec3(got), tangent), radians) << where;
    EXPECT_EQ(got.w, w) << where;
}

void expectUsable(const std::vector<glm::vec4>& frames, const TangentCorners& mesh) {
    ASSERT_EQ(frames.size(), mesh.positions.size());
    for (size_t c = 0; c < frames.size(); ++c) {
        const glm::vec3 t(frames[c]);
        ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z)) << c;
        EXPECT_NEAR(glm::length(t), 1.0f, 1e-5f) << c;
        EXPECT_TRUE(frames[c].w == 1.0f || frames[c].w == -1.0f) << c;
        if (std::isfinite(glm::length(mesh.normals[c])))
            EXPECT_NEAR(glm::dot(t, glm::normalize(mesh.normals[c])), 0.0f, 1e-5f) << c;
    }
}

TEST(TangentGeneration, PlaneUnderAffineUvMapsGetsDpDs) {
    // (s, t) = A (x, y): dP/ds is A^-1's first column; w is the sign of det A.
    const glm::mat2 maps[] = {glm::mat2(1.0f), glm::mat2(0.3f, -0.8f, 1.7f, 0.4f),
                              glm::mat2(-1.0f, 0.0f, 0.0f, 1.0f),
                              glm::mat2(0.2f, 1.1f, 2.0f, -0.5f)};
    for (const glm::mat2& a : maps) {
        const TangentCorners mesh = grid(5, 4, [&](float x, float y) {
            return Vertex{{x, y, 0.0f}, {0.0f, 0.0f, 1.0f}, a * glm::vec2(x, y) + 0.25f};
        });
        const std::vector<glm::vec4> frames = generateTangents(mesh);
        expectUsable(frames, mesh);
        const glm::vec2 dpds = glm::inverse(a)[0];
        const float w = glm::determinant(a) > 0.0f ? 1.0f : -1.0f;
        for (size_t c = 0; c < frames.size(); ++c)
            expectFrame(frames[c], glm::vec3(dpds, 0.0f), w, 1e-4f, std::to_string(c));
    }
}

TEST(TangentGeneration, CylinderMatchesItsAnalyticTangents) {
    // P = (sin 2 pi s, t, cos 2 pi s), outward normals: dP/ds's direction (cos, 0, -sin) at every
    // corner, seam included (u = 0 and u = 1 there).
    const TangentCorners mesh = grid(24, 3, [](float s, float t) {
        const float a = 2 * kPi * s;
        const glm::vec3 radial(std::sin(a), 0.0f, std::cos(a));
        return Vertex{radial + glm::vec3(0.0f, t, 0.0f), radial, {s, t}};
    });
    const std::vector<glm::vec4> frames = generateTangents(mesh);
    expectUsable(frames, mesh);
    for (size_t c = 0; c < frames.size(); ++c) {
        const float a = 2 * kPi * mesh.uvs[c].x;
        expectFrame(frames[c], {std::cos(a), 0.0f, -std::sin(a)}, 1.0f, 1e-3f, std::to_string(c));
        // The bitangent w cross(n, t) is dP/dt = +y.
        const glm::vec3 b = frames[c].w * glm::cross(mesh.normals[c], glm::vec3(frames[c]));
        EXPECT_GT(b.y, 0.9999f) << c;
    }
}

// Largest angle between the generated and the analytic tangent of a sphere band (latitudes
// -60..60 degrees) of n x n/2 quads: faces around a vertex see dP/ds at other latitudes, so the
// frame is exact only in the limit.
float sphereBandError(int n) {
    auto at = [](float s, float t) {
        const float a = 2 * kPi * s, lat = (t - 0.5f) * (2 * kPi / 3);
        const glm::vec3 p(std::cos(lat) * std::sin(a), std::sin(lat), std::cos(lat) * std::cos(a));
        return Vertex{p, p, {s, t}};
    };
    const TangentCorners mesh = grid(n, n / 2, at);
    const std::vector<glm::vec4> frames = generateTangents(mesh);
    expectUsable(frames, mesh);
    float worst = 0.0f;
    for (size_t c = 0; c < frames.size(); ++c) {
        const float a = 2 * kPi * mesh.uvs[c].x;
        EXPECT_EQ(frames[c].w, 1.0f);
        worst = std::max(worst, angleBetween(glm::vec3(frames[c]),
                                             {std::cos(a), 0.0f, -std::sin(a)}));
    }
    return worst;
}

TEST(TangentGeneration, SphereBandConvergesToItsAnalyticTangents) {
    const float coarse = sphereBandError(16), fine = sphereBandError(64);
    EXPECT_LT(coarse, 0.25f); // measured 0.17 rad at 16 segments, 0.043 at 64
    EXPECT_LT(fine, 0.06f);
    EXPECT_LT(fine, coarse / 2.5f) << "error should fall about linearly with the segment size";
}

float faceCentreX(const TangentCorners& mesh, size_t corner) {
    const size_t f = corner / 3 * 3;
    return (mesh.positions[f].x + mesh.positions[f + 1].x + mesh.positions[f + 2].x) / 3;
}

TEST(TangentGeneration, MirroredSeamFlipsHandednessWithoutAveraging) {
    // x in [0, 2]: s = x on the left, s = 2 - x on the right, so the seam's corners (s = 1) are
    // joined but the faces on either side have opposite UV orientation: separate frames.
    const TangentCorners mesh = grid(8, 2, [](float x, float y) {
        const float px = 2 * x;
        return Vertex{{px, y, 0.0f}, {0.0f, 0.0f, 1.0f}, {px <= 1.0f ? px : 2.0f - px, y}};
    });
    const std::vector<glm::vec4> frames = generateTangents(mesh);
    expectUsable(frames, mesh);
    for (size_t c = 0; c < frames.size(); ++c) {
        const bool left = faceCentreX(mesh, c) < 1.0f;
        expectFrame(frames[c], {left ? 1.0f : -1.0f, 0.0f, 0.0f}, left ? 1.0f : -1.0f, 1e-4f,
                    std::to_string(c));
        // Both halves agree on the bitangent: t grows along +y on either side.
        const glm::vec3 b = frames[c].w * glm::cross(mesh.normals[c], glm::vec3(frames[c]));
        EXPECT_GT(b.y, 0.9999f) << c;
    }
}

TEST(TangentGeneration, UvSeamKeepsSharedPositionsApart) {
    // x in [0, 2]. Faces left of x = 1 use (s, t) = (x, y), faces right of it a chart turned by
    // 90 degrees, (s, t) = (y, 5 - x), where dP/ds = +y: the seam's positions are shared, their
    // UVs are not, so joining by position alone would average the two there.
    TangentCorners mesh = grid(6, 3, [](float x, float y) {
        return Vertex{{2 * x, y, 0.0f}, {0.0f, 0.0f, 1.0f}, {0.0f, 0.0f}};
    });
    for (size_t c = 0; c < mesh.positions.size(); ++c) {
        const glm::vec3 p = mesh.positions[c];
        mesh.uvs[c] = faceCentreX(mesh, c) < 1.0f ? glm::vec2(p.x, p.y) : glm::vec2(p.y, 5 - p.x);
    }
    const std::vector<glm::vec4> frames = generateTangents(mesh);
    expectUsable(frames, mesh);
    for (size_t c = 0; c < frames.size(); ++c)
        expectFrame(frames[c],
                    faceCentreX(mesh, c) < 1.0f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0), 1.0f,
                    1e-4f, std::to_string(c));
}

TEST(TangentGeneration, DegenerateUvsGetFiniteFramesFromHealthyNeighbours) {
    TangentCorners mesh;
    const glm::vec3 n(0, 0, 1);
    // (s, t) = (y, -x): dP/ds = +y, where the fallback for a +z normal would be +x.
    const Vertex v0{{0, 0, 0}, n, {0, 0}}, v1{{1, 0, 0}, n, {0, -1}}, v2{{0, 1, 0}, n, {1, 0}};
    addTriangle(mesh, v0, v1, v2);
    // Shares the edge v1-v2 (same UVs there); its third UV lies on that edge's line, so it has
    // no UV area: MikkTSpace lets it join the neighbour's frame at the shared corners.
    addTriangle(mesh, v2, v1, Vertex{{1, 1, 0}, n, {0.5f, -0.5f}});
    // Two equal positions: its corners equal to v0 copy v0's healthy frame.
    addTriangle(mesh, v0, v0, Vertex{{-1, 0, 0}, n, {3, 3}});
    // No UV area and no healthy neighbour: the fallback.
    addTriangle(mesh, Vertex{{5, 0, 0}, n, {2, 2}}, Vertex{{6, 0, 0}, n, {2, 2}},
                Vertex{{5, 1, 0}, n, {2, 2}});
    const std::vector<glm::vec4> frames = generateTangents(mesh);
    expectUsable(frames, mesh);
    for (int c : {0, 1, 2, 3, 4, 6, 7})
        expectFrame(frames[c], {0, 1, 0}, 1.0f, 1e-5f, std::to_string(c));
}

TEST(TangentGeneration, NonFiniteInputGivesFiniteFrames) {
    TangentCorners mesh = grid(3, 3, [](float x, float y) {
        return Vertex{{x, y, 0.0f}, {0.0f, 0.0f, 1.0f}, {x * 1e30f, y * 1e30f}};
    });
    mesh.positions[4] = glm::vec3(NAN);
    mesh.normals[7] = glm::vec3(0.0f);
    mesh.uvs[10] = glm::vec2(INFINITY, NAN);
    const std::vector<glm::vec4> frames = generateTangents(mesh);
    ASSERT_EQ(frames.size(), mesh.positions.size());
    for (const glm::vec4& f : frames) {
        EXPECT_TRUE(std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z));
        EXPECT_NEAR(glm::length(glm::vec3(f)), 1.0f, 1e-5f);
    }
}

glm::vec3 decode(uint32_t packed) { return gpu_types::octDecode(glm::unpackSnorm2x16(packed)); }

TEST(TangentGeneration, LoaderFramesFollowTheNodeTransformAndMirroring) {
    // The corpus cylinder (u = angle / 2 pi, v = 1 - height) at a plain and a mirroring node
    // (scale -1 in x): the world tangent is the transformed dP/du, and the shader's bitangent
    // cross(n, t) x sign is +y, up the image, on both.
    const Scene scene =
        loadGltf(std::string(WF_TEST_CORPUS_DIR) + "/valid/normal_map_cylinder_mirrored.gltf");
    ASSERT_EQ(scene.surface.tangents.size(), 128u);
    ASSERT_EQ(scene.surface.normals.size(), 128u);
    for (size_t i = 0; i < scene.triangles.size(); ++i) {
        const Triangle& tri = scene.triangles[i];
        const bool mirrored = tri.p0.x + tri.p1.x + tri.p2.x > 4.5f; // the node at x = 3
        const glm::vec3 corners[3] = {tri.p0, tri.p1, tri.p2};
        const uint32_t tangents[3] = {scene.surface.tangents[i].t0, scene.surface.tangents[i].t1,
                                      scene.surface.tangents[i].t2};
        const uint32_t normals[3] = {scene.surface.normals[i].n0, scene.surface.normals[i].n1,
                                     scene.surface.normals[i].n2};
        for (int k = 0; k < 3; ++k) {
            glm::vec3 local = corners[k];
            if (mirrored)
                local.x = -(local.x - 3.0f);
            const float a = std::atan2(local.x, local.z);
            glm::vec3 expected(std::cos(a), 0.0f, -std::sin(a));
            if (mirrored)
                expected.x = -expected.x;
            const glm::vec3 t = decode(tangents[k]), n = decode(normals[k]);
            // The seam's corners (angle 0 or 2 pi) have the same tangent either way.
            EXPECT_LT(angleBetween(t, expected), 2e-3f) << i << " " << k;
            const float sign = (scene.surface.tangents[i].signs >> k & 1u) ? -1.0f : 1.0f;
            EXPECT_GT((sign * glm::cross(n, t)).y, 0.999f) << i << " " << k;
        }
    }
}

TEST(TangentGeneration, GeneratedFramesAgreeWithTheFilesMikkTangents) {
    // The same cylinder, once with TANGENT holding its MikkTSpace frames (closed form) and once
    // without: the loader's frames agree corner by corner, handedness included, on both nodes.
    const std::string dir = std::string(WF_TEST_CORPUS_DIR) + "/valid/";
    const Scene given = loadGltf(dir + "normal_map_cylinder_with_tangents.gltf");
    const Scene generated = loadGltf(dir + "normal_map_cylinder_mirrored.gltf");
    ASSERT_EQ(given.surface.tangents.size(), generated.surface.tangents.size());
    for (size_t i = 0; i < given.surface.tangents.size(); ++i) {
        const TriangleTangents& a = given.surface.tangents[i];
        const TriangleTangents& b = generated.surface.tangents[i];
        EXPECT_EQ(a.signs, b.signs) << i;
        for (auto [ta, tb] : {std::pair{a.t0, b.t0}, {a.t1, b.t1}, {a.t2, b.t2}})
            EXPECT_LT(angleBetween(decode(ta), decode(tb)), 2e-3f) << i;
    }
}

} // namespace
} // namespace wf
