// The viewer's playback clock (scene/animation/animation_clock.h): frames at 1/fps, the loop
// over [0, last key], seeking clamped, nothing playing in a static scene.
#include <gtest/gtest.h>

#include "scene/animation/animation_clock.h"

using wf::anim::AnimationClock;

TEST(AnimationClock, StaticSceneNeverPlays) {
    AnimationClock clock(0.0, 24.0);
    EXPECT_FALSE(clock.animated());
    clock.toggle();
    EXPECT_FALSE(clock.playing());
    EXPECT_FALSE(clock.advance(1.0));
    EXPECT_EQ(clock.frame(), 0u);
    EXPECT_DOUBLE_EQ(clock.time(), 0.0);
}

TEST(AnimationClock, PausedClockStands) {
    AnimationClock clock(2.0, 24.0);
    EXPECT_TRUE(clock.animated());
    EXPECT_FALSE(clock.playing());
    EXPECT_FALSE(clock.advance(0.5));
    EXPECT_EQ(clock.frame(), 0u);
}

TEST(AnimationClock, PlaysFrameByFrameAndLoops) {
    AnimationClock clock(2.0, 24.0); // frames 0 .. 48, the loop is 49 frames long
    EXPECT_EQ(clock.lastFrame(), 48u);
    clock.toggle();
    EXPECT_FALSE(clock.advance(0.4 / 24.0)); // within frame 0
    EXPECT_TRUE(clock.advance(0.7 / 24.0));  // 1.1 frames in
    EXPECT_EQ(clock.frame(), 1u);
    EXPECT_DOUBLE_EQ(clock.time(), 1.0 / 24.0);
    EXPECT_TRUE(clock.advance(47.0 / 24.0)); // 48.1 frames: the last frame
    EXPECT_EQ(clock.frame(), 48u);
    EXPECT_DOUBLE_EQ(clock.time(), 2.0);
    EXPECT_TRUE(clock.advance(1.0 / 24.0)); // 49.1 frames: wrapped to frame 0
    EXPECT_EQ(clock.frame(), 0u);
    EXPECT_TRUE(clock.advance(10.0 * 49.0 / 24.0 + 3.0 / 24.0)); // ten loops and 3 frames on
    EXPECT_EQ(clock.frame(), 3u);
    clock.toggle();
    EXPECT_FALSE(clock.advance(1.0));
    EXPECT_EQ(clock.frame(), 3u);
}

TEST(AnimationClock, SeekClampsToTheKeys) {
    AnimationClock clock(2.0, 24.0, 0.5); // --time 0.5 is frame 12
    EXPECT_EQ(clock.frame(), 12u);
    EXPECT_DOUBLE_EQ(clock.time(), 0.5);
    EXPECT_TRUE(clock.seek(5.0));
    EXPECT_EQ(clock.frame(), 48u);
    EXPECT_TRUE(clock.seek(-1.0));
    EXPECT_EQ(clock.frame(), 0u);
    EXPECT_FALSE(clock.seek(0.01)); // still frame 0
    EXPECT_TRUE(clock.seek(1.0));
    EXPECT_EQ(clock.frame(), 24u);
    // Playing on from a seek continues from the frame sought.
    clock.setPlaying(true);
    EXPECT_TRUE(clock.advance(1.0 / 24.0 + 1e-6));
    EXPECT_EQ(clock.frame(), 25u);
}

TEST(AnimationClock, EndBetweenFrames) {
    AnimationClock clock(1.01, 10.0); // keys end 0.1 frame after frame 10
    EXPECT_EQ(clock.lastFrame(), 10u);
    clock.seek(1.01);
    EXPECT_EQ(clock.frame(), 10u);
    EXPECT_DOUBLE_EQ(clock.time(), 1.0);
}
