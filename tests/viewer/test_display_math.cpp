// The display pass's tone curves on the CPU (shaders/types/display_types.h is compiled here
// exactly as display.comp uses it): linear at 0 EV is the PNG preview's mapping, ACES is
// monotonic with a highlight roll-off, and empty or non-finite pixels show black.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "image/png_writer.h"
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

TEST(DisplayMath, EmptyAndNonFinitePixelsAreBlack) {
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(displayColor(vec4(1.0f, 1.0f, 1.0f, 0.0f), 1.0f, WF_TONEMAP_LINEAR), vec3(0.0f));
    EXPECT_EQ(displayColor(vec4(inf, 1.0f, 1.0f, 1.0f), 1.0f, WF_TONEMAP_ACES), vec3(0.0f));
    EXPECT_EQ(displayColor(vec4(1.0f, nan, 1.0f, 1.0f), 1.0f, WF_TONEMAP_LINEAR), vec3(0.0f));
}

} // namespace
} // namespace wf
