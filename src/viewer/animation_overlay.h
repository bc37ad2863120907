// The overlay's playback controls for animated scenes: play / pause (T) and a time slider
// over the animations' keys, labelled with the frame as render --frame counts it. Kept apart
// from overlay.cpp's sections; the viewer re-poses the scene when the time changes.
#pragma once
#include <cstdint>

namespace wf {

struct AnimationFacts {
    bool animated = false; // false: the section is not shown
    bool playing = false;
    double time = 0.0; // seconds, the pose shown
    double end = 0.0;  // the last key
    uint32_t frame = 0;
    double fps = 24.0;
};

struct AnimationActions {
    bool togglePlay = false;
    bool seek = false; // to seekTime
    double seekTime = 0.0;
};

// Inside the overlay's window (an ImGui frame in progress).
void animationSection(const AnimationFacts& facts, AnimationActions& actions);

} // namespace wf
