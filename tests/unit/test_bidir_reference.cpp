// A CPU reference for issue 46's bidirectional estimators: the four shared headers of
// shaders/bidir/ (camera importance, light emission, VCM's MIS in BDPT mode, the adjoint BSDF)
// and bsdf.h, run together as a GPU pass would run them, on the small box of
// bidir_reference_scene.h. Three estimators of every pixel's box-filtered mean radiance, paths
// of at most MAX_LENGTH segments for all of them so they estimate the same truncated sum:
//   path tracing with next-event estimation and MIS (power heuristic): the reference;
//   light tracing: every light vertex splatted onto the image through the camera's importance,
//     plus the camera's direct view of the light (a pinhole cannot be hit);
//   BDPT: every strategy (s, t) with s >= 0 and t >= 1 except s = t = 1 (splatting the light's
//     own points, which vcm_mis.h's strategy set leaves to the camera), weighted by vcm_mis.h.
// Each pixel's estimates must agree within 5 standard errors from independent batches.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "shaders/bidir/adjoint_bsdf.h"
#include "shaders/bidir/light_emission.h"
#include "shaders/bidir/vcm_mis.h"
#include "tests/unit/bidir_reference_scene.h"

namespace {

using namespace wf::test::bidir;
using namespace wf::gpu_types;
using glm::dvec3;
using glm::uvec2;

constexpr int MAX_LENGTH = 5; // segments, camera to light
// Light subpaths per pass (one pass = one sample per pixel): fewer than the 48 pixels, so
// cameraSplatScale is 2, not the 1 that would hide a missing or inverted splat factor.
constexpr uint32_t LIGHT_PATHS = 24u;

// ---- Shared pieces: the light, the camera's per-pixel density, one light subpath ----

const Quad& lightQuad(const Scene& s) { return s.quads[s.light]; }

// The light's emitted ray, from emitTriangle on one of the quad's two halves picked with
// probability 1/2. The pick is folded into pdfA (the header leaves it to the caller), so the
// origin's density is 1 / area, the same as next-event estimation's uniform point.
EmissionSample emitFromLight(const Scene& s, Rng& rng) {
    const Quad& q = lightQuad(s);
    const vec3 p0 = q.corner, p1 = q.corner + q.e1, p2 = p1 + q.e2, p3 = q.corner + q.e2;
    const bool second = rng.uniform() < 0.5f;
    const vec2 uPoint = rng.uniform2(), uDirection = rng.uniform2();
    EmissionSample e = second ? emitTriangle(p0, p2, p3, q.emitted, false, uPoint, uDirection)
                              : emitTriangle(p0, p1, p2, q.emitted, false, uPoint, uDirection);
    e.pdfA *= 0.5f;
    return e;
}

// The camera ray's solid-angle density for one pixel's estimate: the whole image's
// cameraDirectionPdf times the pixel count, the density vcm_mis.h's camera strategies weigh
// against lightPathCount light paths, each of which may splat into that pixel.
float pixelPdfW(const CameraGeometry& c, vec3 w) {
    return cameraDirectionPdf(c, c.position, w) * float(c.width * c.height);
}

struct LightVertex {
    vec3 p;
    int quad;
    vec3 toLight;    // unit, back along the subpath
    vec3 throughput; // emitted cos / pdfs times the adjoint BSDF's weights so far
    VcmSubpathMis mis;
    int segments; // from the light
};

// One light subpath's surface vertices, up to MAX_LENGTH - 1 segments from the light (no
// strategy of at most MAX_LENGTH segments uses a farther one).
void traceLightPath(const Scene& s, const VcmMisConfig& cfg, Rng& rng,
                    std::vector<LightVertex>& path) {
    path.clear();
    EmissionSample e = emitFromLight(s, rng);
    vec3 throughput = emissionThroughput(e);
    VcmSubpathMis mis = vcmStartLight(cfg, e.pdfA, e.pdfA * e.pdfW,
                                      glm::dot(e.normal, e.direction), true, false);
    vec3 o = e.origin, d = e.direction;
    int from = s.light;
    for (int segments = 1; segments < MAX_LENGTH; ++segments) {
        Hit h = intersect(s, o, d, from);
        if (h.quad < 0 || s.quads[h.quad].isLight()) {
            return; // the light is black: what reaches it is absorbed
        }
        const Quad& q = s.quads[h.quad];
        const Frame f = frameOf(q);
        vcmOnHit(cfg, mis, h.t * h.t, std::abs(glm::dot(f.ng, d)));
        const vec3 toLight = -d;
        path.push_back({h.p, h.quad, toLight, throughput, mis, segments});
        if (segments + 1 >= MAX_LENGTH) {
            return;
        }
        const BsdfParams m = lambert(q.albedo);
        const vec3 toLightLocal = f.toLocal(toLight);
        BsdfSample bs;
        if (!bsdfSample(m, toLightLocal, rng.uniform(), rng.uniform2(), bs)) {
            return;
        }
        const vec3 wi = f.toWorld(bs.wi);
        throughput *= bs.weight * adjointThroughputFactor(f.ns, f.ng, toLight, wi, bs.eta);
        vcmOnScatter(cfg, mis, std::abs(glm::dot(f.ng, wi)), bs.pdf,
                     bsdfPdf(m, bs.wi, toLightLocal), bs.isDelta);
        o = h.p;
        d = wi;
        from = h.quad;
    }
}

// A light vertex seen by the camera (t = 1): the splat's pixel, its unweighted value and its
// vcm_mis.h weight. lightPaths: light subpaths per pass (one pass = one sample per pixel).
bool connectToCamera(const Scene& s, const VcmMisConfig& cfg, const LightVertex& y,
                     float lightPaths, uvec2& pixel, vec3& value, float& weight) {
    const CameraGeometry& c = s.camera;
    vec3 w;
    vec2 raster;
    float dist2;
    if (!cameraRasterOfPoint(c, c.position, y.p, w, raster, dist2)) {
        return false;
    }
    const Quad& q = s.quads[y.quad];
    const Frame f = frameOf(q);
    const BsdfParams m = lambert(q.albedo);
    const vec3 toCamera = -w, lightLocal = f.toLocal(y.toLight), cameraLocal = f.toLocal(toCamera);
    const vec3 fy = bsdfEval(m, lightLocal, cameraLocal) * std::abs(cameraLocal.z) *
                    adjointThroughputFactor(f.ns, f.ng, y.toLight, toCamera,
                                            adjointEtaOfPair(m, lightLocal, cameraLocal));
    if (fy == vec3(0.0f) || !visible(s, y.p, y.quad, c.position, -1)) {
        return false;
    }
    const float cosCamera = glm::dot(w, c.forward);
    value = y.throughput * fy *
            (cameraImportance(c, c.position, w) * cosCamera / (dist2 * cameraLensPdf(c)) *
             cameraSplatScale(c, lightPaths));
    const float cameraPdfA = pixelPdfW(c, w) * std::abs(glm::dot(f.ng, toCamera)) / dist2;
    weight = vcmWeightCameraConnect(cfg, y.mis, cameraPdfA, bsdfPdf(m, cameraLocal, lightLocal));
    pixel = glm::min(uvec2(raster), uvec2(c.width - 1u, c.height - 1u));
    return true;
}

// A uniform point on the light for next-event estimation, density 1 / area.
vec3 lightPoint(const Scene& s, Rng& rng) {
    const Quad& q = lightQuad(s);
    const vec2 u = rng.uniform2();
    return q.corner + u.x * q.e1 + u.y * q.e2;
}

float powerHeuristic(float a, float b) { return a * a / (a * a + b * b); }

// ---- The three estimators: one pass adds one sample per pixel to `film` ----

using Film = std::vector<vec3>;

vec3 pathTrace(const Scene& s, uvec2 pixel, Rng& rng) {
    const CameraGeometry& c = s.camera;
    const Quad& light = lightQuad(s);
    vec3 o = c.position, d = cameraRayDirection(c, pixel, rng.uniform2());
    vec3 throughput(1.0f), radiance(0.0f);
    float bsdfPdfW = 0.0f;
    int from = -1;
    for (int segments = 1; segments <= MAX_LENGTH; ++segments) {
        Hit h = intersect(s, o, d, from);
        if (h.quad < 0) {
            break;
        }
        const Quad& q = s.quads[h.quad];
        if (q.isLight()) {
            const float cosLight = -glm::dot(q.normal(), d);
            if (cosLight > 0.0f) {
                const float lightPdfW = h.t * h.t / (cosLight * q.area());
                const float w = segments == 1 ? 1.0f : powerHeuristic(bsdfPdfW, lightPdfW);
                radiance += throughput * q.emitted * w;
            }
            break;
        }
        if (segments == MAX_LENGTH) {
            break;
        }
        const Frame f = frameOf(q);
        const BsdfParams m = lambert(q.albedo);
        const vec3 woLocal = f.toLocal(-d);
        const vec3 toPoint = lightPoint(s, rng) - h.p;
        const float dist2 = glm::dot(toPoint, toPoint);
        const vec3 wi = toPoint / std::sqrt(dist2);
        const float cosLight = -glm::dot(light.normal(), wi);
        if (cosLight > 0.0f && visible(s, h.p, h.quad, h.p + toPoint, s.light)) {
            const vec3 wiLocal = f.toLocal(wi);
            const float lightPdfW = dist2 / (cosLight * light.area());
            const float w = powerHeuristic(lightPdfW, bsdfPdf(m, woLocal, wiLocal));
            radiance += throughput * bsdfEval(m, woLocal, wiLocal) * std::abs(wiLocal.z) *
                        light.emitted * (w / lightPdfW);
        }
        BsdfSample bs;
        if (!bsdfSample(m, woLocal, rng.uniform(), rng.uniform2(), bs)) {
            break;
        }
        throughput *= bs.weight;
        bsdfPdfW = bs.pdf;
        o = h.p;
        d = f.toWorld(bs.wi);
        from = h.quad;
    }
    return radiance;
}

void pathTracingPass(const Scene& s, Rng& rng, Film& film) {
    for (uint32_t y = 0; y < s.camera.height; ++y)
        for (uint32_t x = 0; x < s.camera.width; ++x)
            film[y * s.camera.width + x] += pathTrace(s, uvec2(x, y), rng);
}

// Light tracing: LIGHT_PATHS light subpaths per pass, each vertex splatted.
void lightTracingPass(const Scene& s, Rng& rng, Film& film) {
    const CameraGeometry& c = s.camera;
    const uint32_t pixels = c.width * c.height;
    // The camera's direct view of the light: the one strategy no light subpath can take.
    for (uint32_t p = 0; p < pixels; ++p) {
        vec3 d = cameraRayDirection(c, uvec2(p % c.width, p / c.width), rng.uniform2());
        Hit h = intersect(s, c.position, d, -1);
        if (h.quad == s.light && glm::dot(lightQuad(s).normal(), d) < 0.0f) {
            film[p] += lightQuad(s).emitted;
        }
    }
    const VcmMisConfig cfg = makeVcmMisConfig(1.0f, float(LIGHT_PATHS), 0.0f, true, false);
    std::vector<LightVertex> path;
    for (uint32_t i = 0; i < LIGHT_PATHS; ++i) {
        traceLightPath(s, cfg, rng, path);
        for (const LightVertex& y : path) {
            uvec2 pixel;
            vec3 value;
            float weight;
            if (connectToCamera(s, cfg, y, float(LIGHT_PATHS), pixel, value, weight)) {
                film[pixel.y * c.width + pixel.x] += value;
            }
        }
    }
}

// BDPT: every light subpath splats (t = 1), so lightPathCount is LIGHT_PATHS; pixel i's camera
// subpath connects to light subpath i mod LIGHT_PATHS (pixels sharing one are correlated, which
// the batches' standard errors do not mind).
struct Bdpt {
    const Scene& s;
    VcmMisConfig cfg;
    std::vector<std::vector<LightVertex>> lightPaths;

    explicit Bdpt(const Scene& scene, float exponent)
        : s(scene), cfg(makeVcmMisConfig(exponent, float(LIGHT_PATHS), 0.0f, true, false)),
          lightPaths(LIGHT_PATHS) {}

    // s >= 2, t >= 2: the camera vertex x (`segments` from the camera) to every vertex of its
    // light subpath whose path stays within MAX_LENGTH. Each side's factor is f |cos| on the
    // shading normal towards the other (the light's times the adjoint factor), so only 1 / d^2
    // of the geometry term is left.
    vec3 connect(const std::vector<LightVertex>& lightPath, const Hit& x, const Frame& f,
                 const BsdfParams& m, vec3 woLocal, const VcmSubpathMis& cameraMis,
                 int segments) const {
        vec3 sum(0.0f);
        for (const LightVertex& y : lightPath) {
            if (segments + 1 + y.segments > MAX_LENGTH) {
                continue;
            }
            vec3 d = y.p - x.p;
            const float dist2 = glm::dot(d, d);
            d /= std::sqrt(dist2);
            const vec3 wiLocal = f.toLocal(d);
            const vec3 fx = bsdfEval(m, woLocal, wiLocal) * std::abs(wiLocal.z);
            const Quad& qy = s.quads[y.quad];
            const Frame fy = frameOf(qy);
            const BsdfParams my = lambert(qy.albedo);
            const vec3 lightLocal = fy.toLocal(y.toLight), cameraLocal = fy.toLocal(-d);
            const vec3 fl = bsdfEval(my, lightLocal, cameraLocal) * std::abs(cameraLocal.z) *
                            adjointThroughputFactor(fy.ns, fy.ng, y.toLight, -d,
                                                    adjointEtaOfPair(my, lightLocal, cameraLocal));
            const vec3 value = fx * fl * y.throughput / dist2;
            if (value == vec3(0.0f) || !visible(s, x.p, x.quad, y.p, y.quad)) {
                continue;
            }
            const float w = vcmWeightConnect(
                cfg, cameraMis, y.mis, bsdfPdf(m, woLocal, wiLocal), bsdfPdf(m, wiLocal, woLocal),
                bsdfPdf(my, lightLocal, cameraLocal), bsdfPdf(my, cameraLocal, lightLocal),
                std::abs(glm::dot(f.ng, d)), std::abs(glm::dot(fy.ng, d)), dist2);
            sum += value * w;
        }
        return sum;
    }

    // s = 1: next-event estimation from the camera vertex.
    vec3 nextEvent(const Hit& x, const Frame& f, const BsdfParams& m, vec3 woLocal,
                   const VcmSubpathMis& cameraMis, Rng& rng) const {
        const Quad& light = lightQuad(s);
        const vec3 toPoint = lightPoint(s, rng) - x.p;
        const float dist2 = glm::dot(toPoint, toPoint);
        const vec3 wi = toPoint / std::sqrt(dist2);
        const float cosLight = -glm::dot(light.normal(), wi);
        if (!(cosLight > 0.0f) || !visible(s, x.p, x.quad, x.p + toPoint, s.light)) {
            return vec3(0.0f);
        }
        const vec3 wiLocal = f.toLocal(wi);
        const float directPdfA = 1.0f / light.area();
        const float neePdfW = directPdfA * dist2 / cosLight;
        const float emissionPdfW = directPdfA * cosLight * WF_INV_PI;
        const float w = vcmWeightNee(cfg, cameraMis, neePdfW, bsdfPdf(m, woLocal, wiLocal),
                                     bsdfPdf(m, wiLocal, woLocal), emissionPdfW, cosLight,
                                     std::abs(glm::dot(f.ng, wi)));
        return bsdfEval(m, woLocal, wiLocal) * std::abs(wiLocal.z) * light.emitted *
               (w / neePdfW);
    }

    // The camera subpath of one pixel with every strategy that ends on it (s = 0, 1, >= 2).
    vec3 cameraPath(uvec2 pixel, const std::vector<LightVertex>& lightPath, Rng& rng) const {
        const CameraGeometry& c = s.camera;
        vec3 o = c.position, d = cameraRayDirection(c, pixel, rng.uniform2());
        VcmSubpathMis mis = vcmStartCamera(cfg, pixelPdfW(c, d));
        vec3 throughput(1.0f), radiance(0.0f);
        int from = -1;
        for (int segments = 1; segments <= MAX_LENGTH; ++segments) {
            Hit h = intersect(s, o, d, from);
            if (h.quad < 0) {
                break;
            }
            const Quad& q = s.quads[h.quad];
            const Frame f = frameOf(q);
            vcmOnHit(cfg, mis, h.t * h.t, std::abs(glm::dot(f.ng, d)));
            if (q.isLight()) { // s = 0
                const float cosLight = -glm::dot(q.normal(), d);
                if (cosLight > 0.0f) {
                    const float directPdfA = 1.0f / q.area();
                    // The direct view has weight 1: no strategy splats the light's own points.
                    const float w = segments == 1 ? 1.0f
                                                  : vcmWeightEmitterHit(cfg, mis, directPdfA,
                                                                        directPdfA * cosLight *
                                                                            WF_INV_PI);
                    radiance += throughput * q.emitted * w;
                }
                break;
            }
            if (segments == MAX_LENGTH) {
                break;
            }
            const BsdfParams m = lambert(q.albedo);
            const vec3 woLocal = f.toLocal(-d);
            radiance += throughput * (nextEvent(h, f, m, woLocal, mis, rng) +
                                      connect(lightPath, h, f, m, woLocal, mis, segments));
            BsdfSample bs;
            if (!bsdfSample(m, woLocal, rng.uniform(), rng.uniform2(), bs)) {
                break;
            }
            const vec3 wi = f.toWorld(bs.wi);
            throughput *= bs.weight;
            vcmOnScatter(cfg, mis, std::abs(glm::dot(f.ng, wi)), bs.pdf,
                         bsdfPdf(m, bs.wi, woLocal), bs.isDelta);
            o = h.p;
            d = wi;
            from = h.quad;
        }
        return radiance;
    }

    void pass(Rng& rng, Film& film) {
        const CameraGeometry& c = s.camera;
        const uint32_t pixels = c.width * c.height;
        for (std::vector<LightVertex>& path : lightPaths) {
            traceLightPath(s, cfg, rng, path);
            for (const LightVertex& y : path) { // t = 1
                uvec2 pixel;
                vec3 value;
                float weight;
                if (connectToCamera(s, cfg, y, float(LIGHT_PATHS), pixel, value, weight)) {
                    film[pixel.y * c.width + pixel.x] += value * weight;
                }
            }
        }
        for (uint32_t i = 0; i < pixels; ++i) {
            film[i] += cameraPath(uvec2(i % c.width, i / c.width), lightPaths[i % LIGHT_PATHS],
                                  rng);
        }
    }
};

// ---- Statistics over independent batches ----

struct Estimate {
    std::vector<std::vector<dvec3>> batchMeans; // [batch][pixel]
    std::vector<dvec3> mean, se;
    double seconds = 0.0;
};

uint64_t splitMix(uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

template <class Pass>
Estimate runBatches(const Scene& s, int batches, int passesPerBatch, uint64_t seed, Pass pass) {
    const auto start = std::chrono::steady_clock::now();
    const size_t pixels = s.camera.width * s.camera.height;
    Estimate e;
    Film film(pixels);
    for (int b = 0; b < batches; ++b) {
        Rng rng(splitMix(seed * 1000003ull + uint64_t(b)));
        std::vector<dvec3> sum(pixels, dvec3(0.0));
        for (int p = 0; p < passesPerBatch; ++p) {
            std::fill(film.begin(), film.end(), vec3(0.0f));
            pass(rng, film);
            for (size_t i = 0; i < pixels; ++i) sum[i] += dvec3(film[i]);
        }
        for (dvec3& v : sum) v /= double(passesPerBatch);
        e.batchMeans.push_back(sum);
    }
    e.mean.assign(pixels, dvec3(0.0));
    e.se.assign(pixels, dvec3(0.0));
    for (const auto& bm : e.batchMeans)
        for (size_t i = 0; i < pixels; ++i) e.mean[i] += bm[i] / double(batches);
    for (const auto& bm : e.batchMeans)
        for (size_t i = 0; i < pixels; ++i) {
            dvec3 dev = bm[i] - e.mean[i];
            e.se[i] += dev * dev / double(batches * (batches - 1));
        }
    for (dvec3& v : e.se) v = glm::sqrt(v);
    e.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return e;
}

// The image's mean over pixels and channels, with its standard error over the batches.
std::pair<double, double> imageMean(const Estimate& e) {
    std::vector<double> perBatch;
    for (const auto& bm : e.batchMeans) {
        double m = 0.0;
        for (const dvec3& v : bm) m += (v.x + v.y + v.z) / (3.0 * bm.size());
        perBatch.push_back(m);
    }
    double mean = 0.0, var = 0.0;
    for (double m : perBatch) mean += m / perBatch.size();
    for (double m : perBatch) var += (m - mean) * (m - mean) / (perBatch.size() - 1);
    return {mean, std::sqrt(var / perBatch.size())};
}

constexpr int BATCHES = 64;

const Estimate& pathTracingReference() {
    static const Scene scene = boxScene();
    static const Estimate e = runBatches(scene, BATCHES, 800, 1u, [&](Rng& rng, Film& film) {
        pathTracingPass(scene, rng, film);
    });
    return e;
}

// Per pixel and channel: finite, both standard errors under 3% of the value, and within 5
// combined standard errors; the image means likewise. Prints the figures.
void expectAgreement(const Estimate& test, const char* name) {
    const Estimate& ref = pathTracingReference();
    double maxZ = 0.0, maxRelSe = 0.0;
    for (size_t i = 0; i < ref.mean.size(); ++i)
        for (int ch = 0; ch < 3; ++ch) {
            const double a = ref.mean[i][ch], b = test.mean[i][ch];
            ASSERT_TRUE(std::isfinite(a) && std::isfinite(b)) << name << " pixel " << i;
            const double seA = ref.se[i][ch], seB = test.se[i][ch];
            maxRelSe = std::max({maxRelSe, seA / a, seB / b});
            EXPECT_LT(seA, 0.03 * a) << "path tracing, pixel " << i << " channel " << ch;
            EXPECT_LT(seB, 0.03 * b) << name << ", pixel " << i << " channel " << ch;
            const double z = (b - a) / std::sqrt(seA * seA + seB * seB);
            maxZ = std::max(maxZ, std::abs(z));
            EXPECT_LT(std::abs(z), 5.0) << name << " pixel " << i << " channel " << ch << ": "
                                        << b << " against path tracing's " << a;
        }
    auto [refMean, refSe] = imageMean(ref);
    auto [mean, se] = imageMean(test);
    const double zMean = (mean - refMean) / std::hypot(refSe, se);
    EXPECT_LT(std::abs(zMean), 5.0) << name << " image mean " << mean << " against " << refMean;
    std::printf("%s: max |z| %.2f over %zu pixel channels, max relative SE %.4f, image mean %.5f "
                "(path tracing %.5f, z %.2f); %.1f s (path tracing %.1f s)\n",
                name, maxZ, 3 * ref.mean.size(), maxRelSe, mean, refMean, zMean, test.seconds,
                ref.seconds);
}

TEST(BidirReference, SceneIsWhatTheEstimatorsAssume) {
    const Scene s = boxScene();
    const Quad& light = lightQuad(s);
    EXPECT_NEAR(glm::dot(light.normal(), vec3(0, -1, 0)), 1.0f, 1e-6f); // emits down
    EXPECT_TRUE(cameraConnectable(s.camera));
    // The emitted rays leave the front face from both halves of the quad.
    Rng rng(3u);
    for (int i = 0; i < 1000; ++i) {
        EmissionSample e = emitFromLight(s, rng);
        ASSERT_NEAR(glm::dot(e.normal, light.normal()), 1.0f, 1e-5f);
        ASSERT_NEAR(e.pdfA * light.area(), 1.0f, 1e-4f);
        ASSERT_GT(glm::dot(e.direction, e.normal), 0.0f);
    }
    // The camera sees the light: the direct view is a real part of the image.
    vec3 w;
    vec2 raster;
    float dist2;
    EXPECT_TRUE(cameraRasterOfPoint(s.camera, s.camera.position,
                                    light.corner + 0.5f * light.e1 + 0.05f * light.e2, w, raster,
                                    dist2));
}

TEST(BidirReference, LightTracingAgreesWithPathTracing) {
    const Scene scene = boxScene();
    Estimate e = runBatches(scene, BATCHES, 600, 2u, [&](Rng& rng, Film& film) {
        lightTracingPass(scene, rng, film);
    });
    expectAgreement(e, "light tracing");
}

// The power heuristic leaves the camera's emitter hits almost nothing against next-event
// estimation on this small light; the balance heuristic gives them a share, so a wrong term
// for s = 0 in the light subpath's sums shows as bias too.
TEST(BidirReference, BdptAgreesWithPathTracing) {
    const Scene scene = boxScene();
    for (float exponent : {2.0f, 1.0f}) {
        Bdpt bdpt(scene, exponent);
        Estimate e = runBatches(scene, BATCHES, 150, 3u + uint64_t(exponent),
                                [&](Rng& rng, Film& film) { bdpt.pass(rng, film); });
        expectAgreement(e, exponent == 2.0f ? "bdpt, power heuristic" : "bdpt, balance heuristic");
    }
}

} // namespace
