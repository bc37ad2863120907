// shaders/bidir/vcm_mis.h against the definition of its weights. For abstract paths (random
// vertices, normals, BSDF pdfs, Dirac bounces; each light kind) the reference lists every
// strategy that can sample the path, takes each one's density as a plain product of its
// vertices' area pdfs, and forms (n p)^beta / sum (n p)^beta; the header's recursive weights,
// run along simulated camera and light subpaths, must match it and sum to one.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shaders/bidir/vcm_mis.h"

namespace {

namespace gt = wf::gpu_types;

enum class LightKind { Area, Point, Environment, Directional };

bool isFinite(LightKind l) { return l == LightKind::Area || l == LightKind::Point; }
bool isDiracLight(LightKind l) { return l == LightKind::Point || l == LightKind::Directional; }

struct Mode {
    const char* name;
    float exponent;
    bool connect;
    bool merge;
};

const Mode kModes[] = {
    {"bdpt-balance", 1.0f, true, false}, {"bdpt-power", 2.0f, true, false},
    {"vcm-balance", 1.0f, true, true},   {"vcm-power", 2.0f, true, true},
    {"merge-only-balance", 1.0f, false, true}, {"merge-only-power", 2.0f, false, true},
};

// x0 is a pinhole camera, xk the light: a point for finite lights, a direction (lightDir, from
// x(k-1)) for infinite ones. Dirac lobes' pdfs stand for their lobe probabilities, the delta
// itself being common to every strategy that can sample the path.
struct AbstractPath {
    int k = 0;
    LightKind light = LightKind::Area;
    std::vector<glm::dvec3> x, n;
    glm::dvec3 lightDir{0.0, 0.0, 1.0};
    std::vector<double> pdfFwd; // [0] camera ray; [i] at xi towards x(i+1), arriving from x(i-1)
    std::vector<double> pdfRev; // [i] at xi towards x(i-1), arriving from x(i+1); [k] emission
                                // direction pdf (finite) or disk pdf (infinite)
    std::vector<bool> dirac;    // [1..k-1]
    double lightPosEmit = 1.0;  // emission's pick x position pdf (direction pdf if infinite)
    double lightPosNee = 1.0;   // next-event estimation's, which may differ

    bool finite() const { return isFinite(light); }
    glm::dvec3 dirTo(int i, int j) const {
        if (j == k && !finite()) return lightDir;
        if (i == k && !finite()) return -lightDir;
        return glm::normalize(x[j] - x[i]);
    }
    double cosAt(int i, int toward) const { return std::abs(glm::dot(n[i], dirTo(i, toward))); }
    double dist2(int i, int j) const {
        glm::dvec3 d = x[j] - x[i];
        return glm::dot(d, d);
    }
};

struct Params {
    double lightPathCount;
    double eta;
};

// One way to sample the path: a connection (s light vertices, t camera vertices) or a merge at
// x(t-1); p already includes its sample count n.
struct Strategy {
    int s, t;
    bool merge;
    double np;
};

std::string describe(const AbstractPath& path, const Strategy& st, const Mode& mode) {
    std::ostringstream o;
    o << mode.name << " k=" << path.k << " light=" << int(path.light) << " "
      << (st.merge ? "merge at x" : "connect s=") << (st.merge ? st.t - 1 : st.s)
      << (st.merge ? "" : " t=" + std::to_string(st.t)) << " dirac=";
    for (int i = 1; i < path.k; ++i) o << int(path.dirac[i]);
    return o.str();
}

// The explicit definition: area densities a (camera subpath) and b (light subpath) of every
// vertex, then each strategy's product. Nothing here uses the header.
std::vector<Strategy> explicitStrategies(const AbstractPath& p, const Mode& mode,
                                         const Params& par) {
    const int k = p.k;
    std::vector<double> a(k + 1), b(k + 1);
    a[0] = 1.0; // the pinhole's position: the same delta for every strategy
    for (int i = 1; i <= k; ++i) {
        if (i == k && !p.finite()) a[i] = p.pdfFwd[k - 1];
        else a[i] = p.pdfFwd[i - 1] * p.cosAt(i, i - 1) / p.dist2(i - 1, i);
    }
    b[k] = p.lightPosEmit;
    for (int i = k - 1; i >= 1; --i) {
        if (i == k - 1 && !p.finite()) b[i] = p.pdfRev[k] * p.cosAt(i, k);
        else b[i] = p.pdfRev[i + 1] * p.cosAt(i, i + 1) / p.dist2(i, i + 1);
    }
    auto connectable = [&](int i) { return i == 0 || i == k || !p.dirac[i]; };
    auto density = [&](int t, bool merge) { // camera x0..x(t-1), light x(t or t-1)..xk
        double d = 1.0;
        for (int i = 0; i < t; ++i) d *= a[i];
        bool nee = t == k && !merge; // s = 1: the light point is next-event estimation's
        for (int i = merge ? t - 1 : t; i <= k; ++i) d *= (i == k && nee) ? p.lightPosNee : b[i];
        return d;
    };
    std::vector<Strategy> out;
    if (!isDiracLight(p.light)) out.push_back({0, k + 1, false, density(k + 1, false)});
    if (mode.connect)
        for (int t = 1; t <= k; ++t)
            if (connectable(t - 1) && connectable(t))
                out.push_back({k + 1 - t, t, false,
                               density(t, false) * (t == 1 ? par.lightPathCount : 1.0)});
    if (mode.merge)
        for (int i = 1; i < k; ++i)
            if (!p.dirac[i])
                out.push_back({k + 1 - i, i + 1, true, par.eta * density(i + 1, true)});
    return out;
}

double explicitWeight(const std::vector<Strategy>& all, const Strategy& st, double beta) {
    double sum = 0.0;
    for (const Strategy& o : all) sum += std::pow(o.np, beta);
    return std::pow(st.np, beta) / sum;
}

// Runs both subpaths through the header and returns the weight it gives strategy `st`.
struct RecursiveWeights {
    gt::VcmMisConfig cfg;
    const AbstractPath& p;
    std::vector<gt::VcmSubpathMis> camera, light; // at each vertex, after arriving there

    RecursiveWeights(const AbstractPath& path, const Mode& mode, const Params& par) : p(path) {
        const int k = p.k;
        cfg = gt::makeVcmMisConfig(mode.exponent, float(par.lightPathCount), float(par.eta),
                                   mode.connect, mode.merge);
        camera.resize(k + 1);
        light.resize(k + 1);
        gt::VcmSubpathMis v = gt::vcmStartCamera(cfg, float(p.pdfFwd[0]));
        for (int i = 1; i < k; ++i) {
            gt::vcmOnHit(cfg, v, float(p.dist2(i - 1, i)), float(p.cosAt(i, i - 1)));
            camera[i] = v;
            gt::vcmOnScatter(cfg, v, float(p.cosAt(i, i + 1)), float(p.pdfFwd[i]),
                             float(p.pdfRev[i]), p.dirac[i]);
        }
        if (p.finite()) gt::vcmOnHit(cfg, v, float(p.dist2(k - 1, k)), float(p.cosAt(k, k - 1)));
        camera[k] = v;

        // Infinite lights get a cosine that is not 1: the header must ignore it.
        double cosAtLight = p.finite() ? p.cosAt(k, k - 1) : p.cosAt(k - 1, k);
        v = gt::vcmStartLight(cfg, float(p.lightPosNee), float(emissionPdfW()), float(cosAtLight),
                              p.finite(), isDiracLight(p.light));
        for (int i = k - 1; i >= 1; --i) {
            bool fromInfinite = i == k - 1 && !p.finite();
            gt::vcmOnHit(cfg, v, float(fromInfinite ? 1.0 : p.dist2(i, i + 1)),
                         float(p.cosAt(i, i + 1)));
            light[i] = v;
            gt::vcmOnScatter(cfg, v, float(p.cosAt(i, i - 1)), float(p.pdfRev[i]),
                             float(p.pdfFwd[i]), p.dirac[i]);
        }
    }

    double emissionPdfW() const { return p.lightPosEmit * p.pdfRev[p.k]; }

    double weight(const Strategy& st) const {
        const int k = p.k;
        if (st.merge) {
            int i = st.t - 1;
            return gt::vcmWeightMerge(cfg, camera[i], light[i], float(p.pdfFwd[i]),
                                      float(p.pdfRev[i]));
        }
        if (st.s == 0)
            return gt::vcmWeightEmitterHit(cfg, camera[k], float(p.lightPosNee),
                                           float(emissionPdfW()));
        if (st.s == 1) {
            double cosAtLight = p.finite() ? p.cosAt(k, k - 1) : 1.0;
            double neePdfW =
                p.finite() ? p.lightPosNee * p.dist2(k - 1, k) / cosAtLight : p.lightPosNee;
            double bsdfPdfW = isDiracLight(p.light) ? 0.0 : p.pdfFwd[k - 1];
            return gt::vcmWeightNee(cfg, camera[k - 1], float(neePdfW), float(bsdfPdfW),
                                    float(p.pdfRev[k - 1]), float(emissionPdfW()),
                                    float(cosAtLight), float(p.cosAt(k - 1, k)));
        }
        if (st.t == 1) {
            double cameraPdfA = p.pdfFwd[0] * p.cosAt(1, 0) / p.dist2(0, 1);
            return gt::vcmWeightCameraConnect(cfg, light[1], float(cameraPdfA),
                                              float(p.pdfFwd[1]));
        }
        int c = st.t - 1, l = st.t;
        return gt::vcmWeightConnect(cfg, camera[c], light[l], float(p.pdfFwd[c]),
                                    float(p.pdfRev[c]), float(p.pdfRev[l]), float(p.pdfFwd[l]),
                                    float(p.cosAt(c, l)), float(p.cosAt(l, c)),
                                    float(p.dist2(c, l)));
    }
};

// Compares every strategy's recursive weight with the definition; returns how many strategies
// it compared. Reports at most a few mismatches per call so a broken rule stays readable.
int checkPath(const AbstractPath& path, const Mode& mode, const Params& par) {
    std::vector<Strategy> all = explicitStrategies(path, mode, par);
    RecursiveWeights rec(path, mode, par);
    double sum = 0.0;
    int reported = 0;
    for (const Strategy& st : all) {
        double want = explicitWeight(all, st, mode.exponent);
        double got = rec.weight(st);
        sum += got;
        if (!(std::abs(got - want) <= 1e-4 * want) && reported++ < 3)
            ADD_FAILURE() << describe(path, st, mode) << ": recursive " << got
                          << ", definition " << want;
    }
    if (!all.empty())
        EXPECT_NEAR(sum, 1.0, 1e-4) << mode.name << " k=" << path.k << ": weights do not sum to 1";
    return int(all.size());
}

double logUniform(std::mt19937& rng, double lo, double hi) {
    return lo * std::pow(hi / lo, std::uniform_real_distribution<double>(0.0, 1.0)(rng));
}

glm::dvec3 randomUnit(std::mt19937& rng) {
    std::normal_distribution<double> g;
    return glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
}

// Random vertices in the unit box, no segment shorter than 0.15 and no cosine under 0.1, so the
// float recursion stays far from overflow and the comparison tests the algebra, not rounding.
AbstractPath randomPath(std::mt19937& rng, int k, LightKind light, double diracChance) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (;;) {
        AbstractPath p;
        p.k = k;
        p.light = light;
        int points = p.finite() ? k + 1 : k;
        for (int i = 0; i <= k; ++i) {
            p.x.push_back(glm::dvec3(u(rng), u(rng), u(rng)));
            p.n.push_back(randomUnit(rng));
        }
        p.lightDir = randomUnit(rng);
        p.pdfFwd.resize(k + 1);
        p.pdfRev.resize(k + 1);
        p.dirac.assign(k + 1, false);
        for (int i = 0; i <= k; ++i) {
            p.pdfFwd[i] = logUniform(rng, 0.2, 3.0);
            p.pdfRev[i] = logUniform(rng, 0.2, 3.0);
        }
        for (int i = 1; i < k; ++i) p.dirac[i] = u(rng) < diracChance;
        p.lightPosEmit = logUniform(rng, 0.2, 3.0);
        p.lightPosNee = logUniform(rng, 0.2, 3.0);
        bool ok = true;
        for (int i = 1; i < points; ++i) ok = ok && p.dist2(i - 1, i) > 0.15 * 0.15;
        for (int i = 1; i <= k; ++i) {
            ok = ok && p.cosAt(i - 1, i) > 0.1;
            if (i < k || p.finite()) ok = ok && p.cosAt(i, i - 1) > 0.1;
        }
        if (ok) return p;
    }
}

Params randomParams(std::mt19937& rng) {
    return {std::round(logUniform(rng, 1.0, 100.0)), logUniform(rng, 0.05, 5.0)};
}

TEST(VcmMis, RecursiveWeightsMatchTheDefinition) {
    std::mt19937 rng(46);
    const LightKind lights[] = {LightKind::Area, LightKind::Environment, LightKind::Point,
                                LightKind::Directional};
    int compared = 0;
    for (const Mode& mode : kModes)
        for (LightKind light : lights)
            for (int k = 2; k <= 6; ++k)
                for (int trial = 0; trial < 40; ++trial)
                    compared += checkPath(randomPath(rng, k, light, 0.3), mode, randomParams(rng));
    // Guards against a generator that leaves (almost) nothing to compare.
    std::printf("compared %d strategy weights\n", compared);
    EXPECT_GT(compared, 10000);
}

// vcm_merge.glsl's roulette rests on vcmMergeWeightBound: no merge at a camera vertex weighs
// more than it, whatever the light subpath and the photon's direction.
TEST(VcmMis, MergeWeightsStayUnderTheirBound) {
    std::mt19937 rng(4646);
    int merges = 0, tight = 0;
    for (const Mode& mode : kModes) {
        if (!mode.merge)
            continue;
        for (int k = 2; k <= 6; ++k)
            for (int trial = 0; trial < 200; ++trial) {
                const AbstractPath path = randomPath(rng, k, LightKind::Area, 0.3);
                const Params par = randomParams(rng);
                const RecursiveWeights rec(path, mode, par);
                for (const Strategy& st : explicitStrategies(path, mode, par)) {
                    if (!st.merge)
                        continue;
                    const double weight = rec.weight(st);
                    const double bound = gt::vcmMergeWeightBound(rec.cfg, rec.camera[st.t - 1]);
                    EXPECT_LE(weight, bound * (1.0 + 1e-5)) << describe(path, st, mode);
                    ++merges;
                    tight += weight > 0.5 * bound;
                }
            }
    }
    EXPECT_GT(merges, 1000);
    EXPECT_GT(tight, merges / 20); // a bound that is not merely 1
}

// Camera - specular - specular - emitter: no vertex can be connected or merged, so the camera
// hitting the emitter is the only strategy and must keep the whole weight in every mode.
TEST(VcmMis, OnlyTheEmitterHitSamplesAllSpecularPaths) {
    std::mt19937 rng(7);
    for (const Mode& mode : kModes)
        for (int k = 3; k <= 5; ++k)
            for (int trial = 0; trial < 20; ++trial) {
                AbstractPath path = randomPath(rng, k, LightKind::Area, 1.0);
                Params par = randomParams(rng);
                std::vector<Strategy> all = explicitStrategies(path, mode, par);
                ASSERT_EQ(all.size(), 1u);
                ASSERT_EQ(all[0].s, 0);
                EXPECT_NEAR(RecursiveWeights(path, mode, par).weight(all[0]), 1.0, 1e-6)
                    << mode.name << " k=" << k;
            }
    // One diffuse vertex behind the mirrors: the emitter hit now shares with t = 1 and merging
    // there, never with next-event estimation from the last mirror.
    for (const Mode& mode : kModes)
        for (int trial = 0; trial < 20; ++trial) {
            AbstractPath path = randomPath(rng, 4, LightKind::Area, 1.0);
            path.dirac[1] = false;
            checkPath(path, mode, randomParams(rng));
        }
}

// A pinhole and a point light, camera - diffuse - light: the camera is never hit and the light
// never hit, so next-event estimation (density a1, the camera's) and the light tracer
// (density N b1, the light's) are the only connections. Closed form for the balance heuristic.
TEST(VcmMis, PinholeCameraAndPointLight) {
    std::mt19937 rng(11);
    const Mode bdpt = kModes[0];
    for (int trial = 0; trial < 50; ++trial) {
        AbstractPath path = randomPath(rng, 2, LightKind::Point, 0.0);
        Params par = randomParams(rng);
        double a1 = path.pdfFwd[0] * path.cosAt(1, 0) / path.dist2(0, 1);
        double b1 = path.pdfRev[2] * path.cosAt(1, 2) / path.dist2(1, 2);
        double nee = a1 * path.lightPosNee / path.lightPosEmit;
        double lightTracer = par.lightPathCount * b1;
        RecursiveWeights rec(path, bdpt, par);
        double wNee = rec.weight({1, 2, false, 0.0});
        double wTracer = rec.weight({2, 1, false, 0.0});
        EXPECT_NEAR(wNee, nee / (nee + lightTracer), 1e-5);
        EXPECT_NEAR(wTracer, lightTracer / (nee + lightTracer), 1e-5);
    }
    // Longer paths, Dirac bounces among them, every mode; the light tracer connects to the pinhole
    // only through its importance, and nothing ever hits either end.
    for (const Mode& mode : kModes)
        for (int k = 2; k <= 6; ++k)
            for (int trial = 0; trial < 30; ++trial) {
                AbstractPath path = randomPath(rng, k, LightKind::Point, 0.3);
                Params par = randomParams(rng);
                for (const Strategy& st : explicitStrategies(path, mode, par))
                    ASSERT_GE(st.s, 1) << "a point light cannot be hit";
                checkPath(path, mode, par);
            }
}

} // namespace
