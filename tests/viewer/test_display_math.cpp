// The display pass's tone curves on the CPU (shaders/types/display_types.h is compiled here
// exactly as display.comp uses it): linear at 0 EV is the PNG preview's mapping, ACES is
// monotonic with a highlight roll-off, Khronos PBR Neutral matches its definition and the PNG
// preview's, and empty or non-finite pixels show black.
#include <algorithm>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "image/png_writer.h"
#include "image/tonemap.h"
#include "shaders/types/display_types.h"

namespace wf {
namespace {

using namespace gpu_types;

TEST(DisplayMath, LinearAtZeroEvIsThePngPreview) {
    for (int i = 0; i <= 1200; ++i) {
        const float v = i / 1000.0f;
        const vec3 shown = displayColor(vec4(v, v, v, 1.0f), 1.0f, WF_TONEMAP_LINEAR);
        // The GPU rounds in packUnorm4x8 as the PNG writer does; allow pow's last bit.
        EXPECT_NEAR(std::lround(shown.x * 255.0f), linearToSrgb8(v), 1) << "at " << v;
    }
}

TEST(DisplayMath, MeanOfTheSamplesAndExposure) {
    const vec3 a = displayColor(vec4(0.8f, 0.8f, 0.8f, 4.0f), 1.0f, WF_TONEMAP_LINEAR);
    const vec3 b = displayColor(vec4(0.1f, 0.1f, 0.1f, 1.0f), 2.0f, WF_TONEMAP_LINEAR);
    EXPECT_FLOAT_EQ(a.x, srgbEncode(0.2f));
    EXPECT_FLOAT_EQ(b.x, srgbEncode(0.2f));
}

TEST(DisplayMath, AcesIsMonotonicAndRollsOff) {
    EXPECT_NEAR(tonemapAces(vec3(0.0f)).x, 0.0f, 1e-6f);
    float previous = 0.0f;
    for (int i = 1; i <= 2000; ++i) {
        const float y = tonemapAces(vec3(i / 100.0f)).x;
        EXPECT_GE(y, previous);
        EXPECT_LE(y, 1.0f);
        previous = y;
    }
    EXPECT_LT(tonemapAces(vec3(1.0f)).x, 1.0f); // linear would already clip here
    EXPECT_GT(tonemapAces(vec3(16.0f)).x, 0.99f);
}

// Khronos PBR Neutral written out again in double, from the curve's published definition, so
// a slip in display_types.h shows.
double neutralReference(double r, double g, double b, int channel) {
    const double start = 0.8 - 0.04, desaturation = 0.15;
    const double lowest = std::min({r, g, b});
    const double offset = lowest < 0.08 ? lowest - 6.25 * lowest * lowest : 0.04;
    double c[3] = {r - offset, g - offset, b - offset};
    const double peak = std::max({c[0], c[1], c[2]});
    if (peak < start)
        return std::clamp(c[channel], 0.0, 1.0);
    const double d = 1.0 - start;
    const double newPeak = 1.0 - d * d / (peak + d - start);
    const double scaled = c[channel] * newPeak / peak;
    const double t = 1.0 - 1.0 / (desaturation * (peak - newPeak) + 1.0);
    return std::clamp(scaled + (newPeak - scaled) * t, 0.0, 1.0);
}

TEST(DisplayMath, NeutralMatchesItsDefinition) {
    const double colours[][3] = {{0.0, 0.0, 0.0}, {0.02, 0.05, 0.01}, {0.18, 0.18, 0.18},
                                 {0.5, 0.2, 0.1}, {0.7, 0.75, 0.72}, {0.9, 0.4, 0.2},
                                 {2.0, 1.0, 0.5}, {10.0, 3.0, 1.0}, {100.0, 100.0, 100.0}};
    for (const auto& c : colours) {
        const vec3 mapped = tonemapNeutral(vec3(float(c[0]), float(c[1]), float(c[2])));
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(mapped[k], neutralReference(c[0], c[1], c[2], k), 2e-6)
                << c[0] << " " << c[1] << " " << c[2] << " channel " << k;
    }
}

TEST(DisplayMath, NeutralKeepsBaseColoursAndRollsOffHighlights) {
    // A base colour below the knee comes out as it went in, less the 0.04 lift.
    const vec3 base = tonemapNeutral(vec3(0.5f, 0.3f, 0.2f));
    EXPECT_NEAR(base.x, 0.46f, 1e-6f);
    EXPECT_NEAR(base.y, 0.26f, 1e-6f);
    EXPECT_NEAR(base.z, 0.16f, 1e-6f);
    float previous = 0.0f;
    for (int i = 0; i <= 5000; ++i) {
        const float y = tonemapNeutral(vec3(i / 100.0f)).x;
        EXPECT_GE(y, previous) << "at " << i / 100.0f;
        EXPECT_LE(y, 1.0f);
        previous = y;
    }
    EXPECT_LT(tonemapNeutral(vec3(1.0f)).x, 1.0f); // linear would already clip here
    EXPECT_GT(tonemapNeutral(vec3(50.0f)).x, 0.99f);
    // The GPU's display and the PNG preview agree within an 8-bit step.
    for (float v : {0.01f, 0.18f, 0.7f, 1.5f, 6.0f}) {
        const float rgb[3] = {v, 0.5f * v, 0.25f * v};
        unsigned char png[3];
        tonemapToSrgb8(rgb, Tonemap::Neutral, png);
        const vec3 shown = displayColor(vec4(rgb[0], rgb[1], rgb[2], 1.0f), 1.0f,
                                        WF_TONEMAP_NEUTRAL);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(std::lround(shown[k] * 255.0f), png[k], 1) << v;
    }
}

TEST(DisplayMath, EmptyAndNonFinitePixelsAreBlack) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(displayColor(vec4(1.0f, 1.0f, 1.0f, 0.0f), 1.0f, WF_TONEMAP_LINEAR), vec3(0.0f));
    EXPECT_EQ(displayColor(vec4(inf, 1.0f, 1.0f, 1.0f), 1.0f, WF_TONEMAP_ACES), vec3(0.0f));
    EXPECT_EQ(displayColor(vec4(1.0f, nan, 1.0f, 1.0f), 1.0f, WF_TONEMAP_LINEAR), vec3(0.0f));
}

} // namespace
} // namespace wf
