#include "light_agreement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "gpu_test_util.h"
#include "image/exr_io.h"

namespace wf::test {
namespace {

struct PixelStatistics {
    std::vector<double> mean;     // over seeds
    std::vector<double> variance; // of one seed's value, from the spread over seeds
};

PixelStatistics renderSeeds(const Scene& scene, const AgreementMethod& method,
                            const AgreementOptions& options) {
    const size_t pixels = size_t(options.size) * options.size;
    std::vector<double> sum(pixels, 0.0), sumSq(pixels, 0.0);
    for (int seed = 0; seed < options.seeds; ++seed) {
        RenderSettings settings;
        settings.width = settings.height = options.size;
        settings.samplesPerPixel = options.spp;
        settings.maxDepth = 2;
        settings.seed = 7000u + uint32_t(seed);
        settings.lightSampling = method.lightSampling;
        settings.triangleSolidAngle = settings.sphereSolidAngle = method.solidAngle;
        settings.lightSelection = method.selection;
        RenderResult result = renderScene(scene, settings);
        EXPECT_EQ(result.stats.nonFiniteSamples, 0u) << method.name;
        for (size_t i = 0; i < pixels; ++i) {
            const double v = (result.rgb[3 * i] + result.rgb[3 * i + 1] + result.rgb[3 * i + 2]) / 3.0;
            sum[i] += v;
            sumSq[i] += v * v;
        }
    }
    PixelStatistics stats{std::vector<double>(pixels), std::vector<double>(pixels)};
    const double k = options.seeds;
    for (size_t i = 0; i < pixels; ++i) {
        stats.mean[i] = sum[i] / k;
        stats.variance[i] = std::max(0.0, sumSq[i] - sum[i] * sum[i] / k) / (k - 1.0);
    }
    return stats;
}

void writeGrey(const std::filesystem::path& path, uint32_t size, const std::vector<double>& v) {
    std::vector<float> rgb(v.size() * 3);
    for (size_t i = 0; i < v.size(); ++i)
        rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = float(v[i]);
    writeExr(path.string(), int(size), int(size), rgb);
}

// Actual, expected and actual / expected (0 where not compared), for a person to look at.
std::string writeFailureImages(const std::string& stem, uint32_t size, const PixelStatistics& actual,
                               const ExpectedImage& expected) {
    const std::filesystem::path folder(WF_TEST_OUTPUT_DIR);
    std::filesystem::create_directories(folder);
    std::vector<double> ratio(actual.mean.size(), 0.0);
    for (size_t i = 0; i < ratio.size(); ++i)
        if (expected.valid[i] && expected.value[i] > 0.0)
            ratio[i] = actual.mean[i] / expected.value[i];
    writeGrey(folder / (stem + "_actual.exr"), size, actual.mean);
    writeGrey(folder / (stem + "_expected.exr"), size, expected.value);
    writeGrey(folder / (stem + "_ratio.exr"), size, ratio);
    return (folder / (stem + "_{actual,expected,ratio}.exr")).string();
}

} // namespace

void expectAgreement(const std::string& name, const LightRig& rig, const AgreementMethod& method,
                     const AgreementOptions& options) {
    const uint32_t size = options.size, block = options.block, blocks = size / block;
    // One closed-form image per case, whatever the methods compared with it.
    static std::map<std::string, ExpectedImage> expectedByCase;
    auto known = expectedByCase.find(name);
    if (known == expectedByCase.end())
        known = expectedByCase.emplace(name, expectedDirectLight(rig, size, size)).first;
    const ExpectedImage& expected = known->second;
    const PixelStatistics actual = renderSeeds(rigScene(rig), method, options);

    double expectedMean = 0.0;
    for (size_t i = 0; i < expected.value.size(); ++i)
        expectedMean += expected.value[i] / expected.value.size();
    // A block fails when its mean misses the closed form by more than 5 standard errors plus
    // what the closed form's 8x8 positions per pixel and float rounding can account for.
    int compared = 0, failed = 0;
    std::string map;
    for (uint32_t by = 0; by < blocks; ++by) {
        for (uint32_t bx = 0; bx < blocks; ++bx) {
            double sum = 0.0, sumExpected = 0.0, variance = 0.0, fewestHits = 1e30;
            int count = 0;
            for (uint32_t y = by * block; y < (by + 1) * block; ++y)
                for (uint32_t x = bx * block; x < (bx + 1) * block; ++x) {
                    const size_t i = size_t(y) * size + x;
                    if (!expected.valid[i])
                        continue;
                    sum += actual.mean[i];
                    sumExpected += expected.value[i];
                    variance += actual.variance[i] / options.seeds;
                    fewestHits = std::min(fewestHits, options.spp * expected.hitProbability[i]);
                    ++count;
                }
            char cell[16];
            // Mostly a light or the sky, or a light too rarely found: not compared.
            if (2 * count < int(block * block) || fewestHits < options.minLightHits) {
                map += "    -  ";
                continue;
            }
            const double mean = sum / count, want = sumExpected / count;
            const double standardError = std::sqrt(variance) / count;
            const bool ok = std::abs(mean - want) <=
                            5.0 * standardError + 3e-3 * want + 1e-5 * expectedMean;
            ++compared;
            failed += ok ? 0 : 1;
            std::snprintf(cell, sizeof cell, " %5.3f%c", want > 0.0 ? mean / want : mean,
                          ok ? ' ' : '*');
            map += cell;
        }
        map += "\n";
    }
    if (options.minLightHits == 0.0)
        EXPECT_GT(compared, int(blocks * blocks) / 4) << name << ": too few regions to compare";
    if (failed > 0) {
        const std::string images = writeFailureImages(name + "_" + method.name, size, actual, expected);
        ADD_FAILURE() << name << ", " << method.name << ": " << failed << " of " << compared
                      << " regions disagree with the closed form (*; actual / expected per "
                      << block << "x" << block << " block):\n"
                      << map << "images: " << images;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

} // namespace wf::test
