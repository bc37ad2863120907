#include "scene/animation/animation_clock.h"

#include <algorithm>
#include <cmath>

namespace wf::anim {

namespace {
// Frame numbers of times that are whole frames in decimal (0.5 s at 24 fps) must not fall one
// short by rounding: the same tolerance as --frame's time N / fps read back.
constexpr double kFrameSlack = 1e-9;
} // namespace

AnimationClock::AnimationClock(double end, double fps, double start)
    : end_(std::isfinite(end) && end > 0.0 ? end : 0.0), fps_(fps > 0.0 ? fps : 24.0),
      lastFrame_(uint32_t(std::min(std::floor(end_ * fps_ + kFrameSlack), 1e9))) {
    seek(start);
}

bool AnimationClock::advance(double seconds) {
    if (!playing_ || !(seconds > 0.0))
        return false;
    const double period = double(lastFrame_ + 1) / fps_; // the last frame shows for 1/fps too
    clock_ = std::fmod(clock_ + seconds, period);
    const uint32_t frame =
        std::min(uint32_t(std::floor(clock_ * fps_ + kFrameSlack)), lastFrame_);
    const bool changed = frame != frame_;
    frame_ = frame;
    return changed;
}

bool AnimationClock::seek(double time) {
    const double t = std::isfinite(time) ? std::clamp(time, 0.0, end_) : 0.0;
    const uint32_t frame = std::min(uint32_t(std::floor(t * fps_ + kFrameSlack)), lastFrame_);
    clock_ = double(frame) / fps_;
    const bool changed = frame != frame_;
    frame_ = frame;
    return changed;
}

} // namespace wf::anim
