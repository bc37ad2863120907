// Playback time for the viewer: the animations play from 0 to their last key in a loop at
// wall-clock speed, shown frame by frame (frame n is the time n / fps, as render --frame n
// poses it), so a re-pose happens only when the frame changes and never more often than fps
// times a second. Pure arithmetic, so the unit tests check it without a window.
#pragma once
#include <cstdint>

namespace wf::anim {

class AnimationClock {
public:
    // `end`: the animations' last key time (0: nothing moves); `fps` > 0; starts paused at
    // `start` (clamped into [0, end]).
    AnimationClock(double end, double fps, double start = 0.0);

    bool animated() const { return lastFrame_ > 0; }
    bool playing() const { return playing_; }
    void setPlaying(bool playing) { playing_ = playing && animated(); }
    void toggle() { setPlaying(!playing_); }

    // `seconds` of wall-clock time passed: while playing the time moves on, after the last
    // frame wrapping to frame 0. Returns true when the frame changed.
    bool advance(double seconds);
    // Jumps to the frame at `time` (clamped into [0, end]); true when the frame changed.
    bool seek(double time);

    uint32_t frame() const { return frame_; }
    uint32_t lastFrame() const { return lastFrame_; } // the frame of the last key
    double time() const { return double(frame_) / fps_; } // the pose shown
    double end() const { return end_; }
    double fps() const { return fps_; }

private:
    double end_;
    double fps_;
    uint32_t lastFrame_;
    double clock_ = 0.0; // seconds into the loop of lastFrame_ + 1 frames
    uint32_t frame_ = 0;
    bool playing_ = false;
};

} // namespace wf::anim
