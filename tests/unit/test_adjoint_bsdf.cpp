// The adjoint BSDF factors (shaders/bidir/adjoint_bsdf.h) against their definitions: the
// shading-normal correction for random normals and directions (grazing and opposite sides
// included), the per-vertex and whole-path symmetry it restores between radiance and importance
// throughput, and the refraction factor through a smooth slab and on rough glass samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "chi_square.h"
#include "shaders/bidir/adjoint_bsdf.h"

namespace {

using glm::dvec3;
using glm::vec3;
using namespace wf::gpu_types;

using wf::test::uniform01;

vec3 randomDirection(std::mt19937& rng) {
    return wf::test::sphereDirection(2.0 * uniform01(rng) - 1.0, 6.283185307 * uniform01(rng));
}

// A shading normal tilted from ng by up to ~50 degrees, on ng's side as surface.glsl keeps it.
vec3 perturbed(vec3 ng, std::mt19937& rng) {
    vec3 ns;
    do {
        ns = glm::normalize(ng + 0.8f * randomDirection(rng));
    } while (!(glm::dot(ns, ng) > 0.2f));
    return ns;
}

// A world direction in the shading frame of ns (+z = ns), as path_vertex.glsl builds it.
vec3 toLocal(vec3 ns, vec3 w) {
    vec3 t, b;
    buildOrthonormalBasis(ns, t, b);
    return vec3(glm::dot(w, t), glm::dot(w, b), glm::dot(w, ns));
}

double definition(vec3 ns, vec3 ng, vec3 toLight, vec3 toCamera) {
    dvec3 n(ns), g(ng), l(toLight), c(toCamera);
    return std::abs(glm::dot(l, n)) * std::abs(glm::dot(c, g)) /
           (std::abs(glm::dot(l, g)) * std::abs(glm::dot(c, n)));
}

BsdfParams material(vec3 color, float roughness, float transmission, float ior = 1.5f) {
    return BsdfParams{color, 0.0f, roughness, ior, transmission, 1.0f, vec3(1.0f)};
}

TEST(AdjointBsdf, ShadingFactorMatchesDefinition) {
    std::mt19937 rng(46u);
    int opposite = 0;
    for (int i = 0; i < 20000; ++i) {
        vec3 ng = randomDirection(rng);
        // Any pair, tilted shading normals, and normals on opposite sides (back-facing ns).
        vec3 ns = i % 3 == 0 ? randomDirection(rng) : perturbed(i % 3 == 1 ? ng : -ng, rng);
        vec3 l = randomDirection(rng), c = randomDirection(rng);
        if (i % 5 == 0) // near-grazing on the geometry
            l = glm::normalize(l - glm::dot(l, ng) * ng * (1.0f - 1e-3f * uniform01(rng)));
        opposite += (glm::dot(l, ns) > 0.0f) != (glm::dot(l, ng) > 0.0f);
        float got = adjointShadingFactor(ns, ng, l, c);
        double want = definition(ns, ng, l, c);
        ASSERT_TRUE(std::isfinite(got)) << i;
        // Float dot products err by ~2e-7 absolutely, so each cosine relatively by 2e-7 / |cos|.
        double conditioning = 0.0;
        for (float cosine : {glm::dot(l, ns), glm::dot(l, ng), glm::dot(c, ns), glm::dot(c, ng)})
            conditioning += 1.0 / std::max(std::abs(double(cosine)), 1e-30);
        if (std::isfinite(want) && want < 1e6)
            EXPECT_NEAR(got, want, want * (1e-6 + 4e-7 * conditioning)) << i;
    }
    EXPECT_GT(opposite, 2000); // the opposite-side cases keep the ratio, checked above
    // Exactly tangent: arriving along the geometry, or leaving in the shading plane, gives 0.
    vec3 ng(0.0f, 0.0f, 1.0f), ns = glm::normalize(vec3(0.3f, 0.0f, 1.0f));
    vec3 up = glm::normalize(vec3(0.2f, 0.5f, 0.8f));
    EXPECT_EQ(adjointShadingFactor(ns, ng, vec3(0.0f, 1.0f, 0.0f), up), 0.0f);
    EXPECT_EQ(adjointShadingFactor(ns, ng, up, vec3(0.0f, 1.0f, 0.0f)), 0.0f);
    EXPECT_EQ(adjointShadingFactor(ng, ng, vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f)), 0.0f);
    // Without shading normals nothing changes.
    EXPECT_NEAR(adjointShadingFactor(ng, ng, up, vec3(0.6f, 0.0f, -0.8f)), 1.0f, 1e-6f);
}

// Per vertex, radiance throughput f(toCamera, toLight) |toLight.ns| times |toCamera.ng| equals
// importance throughput f(toLight, toCamera) |toCamera.ns| c times |toLight.ng|: both are
// f_s |toLight.ng| |toCamera.ng|, the vertex's factor in the path's measurement contribution.
TEST(AdjointBsdf, LambertReciprocityRestored) {
    std::mt19937 rng(47u);
    const BsdfParams lambert = material(vec3(0.7f, 0.5f, 0.3f), 0.5f, 0.0f);
    int compared = 0, uncorrectedDiffers = 0;
    for (int i = 0; i < 20000; ++i) {
        vec3 ng = randomDirection(rng), ns = perturbed(ng, rng);
        vec3 l = randomDirection(rng), c = randomDirection(rng);
        vec3 lL = toLocal(ns, l), cL = toLocal(ns, c);
        float radiance = diffuseOnlyEval(lambert, cL, lL).x * std::abs(lL.z);
        float importance = diffuseOnlyEval(lambert, lL, cL).x * std::abs(cL.z);
        float gl = std::abs(glm::dot(l, ng)), gc = std::abs(glm::dot(c, ng));
        if (!(radiance > 0.0f) || gl < 1e-2f || std::abs(cL.z) < 1e-2f)
            continue;
        ++compared;
        float lhs = radiance * gc;
        float rhs = importance * adjointShadingFactor(ns, ng, l, c) * gl;
        EXPECT_NEAR(rhs, lhs, 1e-4f * lhs) << i;
        uncorrectedDiffers += std::abs(importance * gl - lhs) > 1e-2f * lhs;
    }
    EXPECT_GT(compared, 5000);
    EXPECT_GT(uncorrectedDiffers, compared / 2); // the test needs the correction to pass
}

// Whole path x0 (light, normal n0) -> x1 (rough plastic) -> x2 (rough glass) -> x3 (camera,
// normal n3), Le = We = 1, a_k both adjoint factors at x_k. In area measure the path tracer's
// contribution is (c3: the camera's own cosine, from We cos / pdf)
//   |c3| prod_k f_k(toCamera, toLight) |toLight.ns_k| prod_edges |cos_g at light end| / d^2,
// the light tracer's (c0: the light's own cosine)
//   |c0| prod_k f_k(toLight, toCamera) |toCamera.ns_k| a_k prod_edges |cos_g at camera end| / d^2,
// and both must be Veach's integrand prod G f_s with f_s = f |toLight.ns| / |toLight.ng|.
TEST(AdjointBsdf, GltfPathContributionsAgree) {
    std::mt19937 rng(48u);
    const BsdfParams plastic = material(vec3(0.8f, 0.5f, 0.3f), 0.4f, 0.0f);
    const BsdfParams glass = material(vec3(0.9f, 0.9f, 1.0f), 0.35f, 1.0f, 1.5f);
    int compared = 0, uncorrectedDiffers = 0;
    for (int i = 0; i < 40000; ++i) {
        vec3 x[4], ng[4], ns[4];
        for (int k = 0; k < 4; ++k) {
            x[k] = 2.0f * randomDirection(rng) * (0.3f + uniform01(rng));
            ng[k] = randomDirection(rng);
            ns[k] = k == 1 || k == 2 ? perturbed(ng[k], rng) : ng[k];
        }
        // The ends' own cosines: the camera's in We cos / pdf, the light's in Le cos / pdf.
        double pt = std::abs(glm::dot(ng[3], glm::normalize(x[2] - x[3])));
        double lt = std::abs(glm::dot(ng[0], glm::normalize(x[1] - x[0])));
        double uncorrected = lt, truth = 1.0;
        for (int k = 0; k < 3; ++k) { // edge (x[k] light side, x[k+1] camera side)
            vec3 d = x[k + 1] - x[k];
            double d2 = glm::dot(d, d);
            d = glm::normalize(d);
            double gLight = std::abs(glm::dot(d, ng[k]));
            double gCamera = std::abs(glm::dot(d, ng[k + 1]));
            pt *= gLight / d2;
            lt *= gCamera / d2;
            uncorrected *= gCamera / d2;
            truth *= gLight * gCamera / d2;
        }
        for (int k = 1; k <= 2; ++k) {
            const BsdfParams& m = k == 1 ? plastic : glass;
            vec3 l = glm::normalize(x[k - 1] - x[k]), c = glm::normalize(x[k + 1] - x[k]);
            vec3 lL = toLocal(ns[k], l), cL = toLocal(ns[k], c);
            double fRad = bsdfEval(m, cL, lL).x, fImp = bsdfEval(m, lL, cL).x;
            float a = adjointThroughputFactor(ns[k], ng[k], l, c, adjointEtaOfPair(m, lL, cL));
            pt *= fRad * std::abs(lL.z);
            lt *= fImp * std::abs(cL.z) * a;
            uncorrected *= fImp * std::abs(cL.z);
            truth *= fRad * std::abs(lL.z) / std::abs(glm::dot(l, ng[k]));
        }
        if (!(truth > 1e-6) || !(truth < 1e6))
            continue;
        ++compared;
        EXPECT_NEAR(pt, truth, 1e-4 * truth) << i;
        EXPECT_NEAR(lt, truth, 3e-3 * truth) << i; // bsdf.h's own reciprocity holds to ~1e-3
        uncorrectedDiffers += std::abs(uncorrected - truth) > 1e-2 * truth;
    }
    EXPECT_GT(compared, 1000);
    EXPECT_GT(uncorrectedDiffers, compared / 2); // the test needs the factors to pass
}

// Importance-mode sample weights of rough glass and plastic are the physical BSDF
// f_s(toLight -> toCamera) = bsdfEval(toCamera, toLight) |toCamera.z| over the sampling pdf.
TEST(AdjointBsdf, SampledWeightIsBsdfInRadianceOrder) {
    std::mt19937 rng(49u);
    for (float ior : {1.5f, 1.2f, 2.2f}) {
        const BsdfParams glass = material(vec3(0.9f, 0.8f, 1.0f), 0.3f, 1.0f, ior);
        int refracted = 0;
        for (int i = 0; i < 20000; ++i) {
            vec3 l = randomDirection(rng);
            BsdfSample s;
            if (!bsdfSample(glass, l, uniform01(rng), vec2(uniform01(rng), uniform01(rng)), s) ||
                s.isDelta)
                continue;
            EXPECT_EQ(adjointEtaOfPair(glass, l, s.wi), s.eta) << i;
            refracted += s.eta != 1.0f;
            vec3 want = bsdfEval(glass, s.wi, l) * (std::abs(s.wi.z) / s.pdf);
            vec3 got = s.weight * adjointRefractionFactor(s.eta);
            for (int k = 0; k < 3; ++k)
                EXPECT_NEAR(got[k], want[k], 2e-3f * want[k] + 1e-6f) << ior << " " << i;
        }
        EXPECT_GT(refracted, 2000) << ior;
    }
}

// Smooth white glass (F + T = 1, so a refraction's weight is 1 / eta^2 in radiance mode). A light
// subpath enters at the top face and leaves by the parallel bottom one; the camera path walks the
// same segments the other way. Importance is 1 inside and after; radiance's two crossings cancel.
TEST(AdjointBsdf, SmoothSlabKeepsImportance) {
    const float ior = 1.5f;
    const BsdfParams glass = material(vec3(1.0f), 0.0f, 1.0f, ior);
    const float pick = 0.999f; // uLobe beyond the reflection's share: refract
    vec3 toLight = glm::normalize(vec3(0.4f, -0.3f, 0.8f)); // top face: +z outside
    BsdfSample in;
    ASSERT_TRUE(bsdfSample(glass, toLight, pick, vec2(0.5f), in));
    ASSERT_TRUE(in.isDelta && in.wi.z < 0.0f && in.eta == ior);
    float inside = in.weight.x * adjointRefractionFactor(in.eta);
    EXPECT_NEAR(inside, 1.0f, 1e-5f);
    // Bottom face: outside is world -z; its frame is (x, -y, -z). The light arrives from -in.wi.
    vec3 d = in.wi;
    BsdfSample out;
    ASSERT_TRUE(bsdfSample(glass, vec3(-d.x, d.y, d.z), pick, vec2(0.5f), out));
    ASSERT_TRUE(out.isDelta && out.wi.z > 0.0f && std::abs(out.eta - 1.0f / ior) < 1e-7f);
    vec3 exit(out.wi.x, -out.wi.y, -out.wi.z);
    EXPECT_NEAR(glm::dot(exit, -toLight), 1.0f, 1e-5f); // leaves parallel to how it came
    float through = inside * out.weight.x * adjointRefractionFactor(out.eta);
    EXPECT_NEAR(through, 1.0f, 1e-5f);
    // Radiance: the camera path enters at the bottom (wo = toCamera outside) and leaves at the top.
    BsdfSample camIn, camOut;
    ASSERT_TRUE(bsdfSample(glass, out.wi, pick, vec2(0.5f), camIn));
    ASSERT_TRUE(bsdfSample(glass, in.wi, pick, vec2(0.5f), camOut));
    EXPECT_NEAR(camIn.weight.x, 1.0f / (ior * ior), 1e-5f);
    EXPECT_NEAR(camOut.weight.x, ior * ior, 1e-4f);
    EXPECT_NEAR(camIn.weight.x * camOut.weight.x, 1.0f, 1e-5f);
    // One crossing (the top face, same pair of directions): the modes differ by eta^2.
    EXPECT_NEAR(camOut.weight.x / inside, ior * ior, 1e-4f);
}

} // namespace
