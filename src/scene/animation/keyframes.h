// One glTF animation sampler as numbers: strictly increasing key times and, per key, `width`
// values (3 for translation and scale, 4 for a rotation quaternion x y z w, the morph target
// count for weights). CUBICSPLINE keys hold three groups each: in-tangent, value, out-tangent.
#pragma once
#include <cstddef>
#include <vector>

#include <glm/gtc/quaternion.hpp>

namespace wf::anim {

enum class Interpolation { Step, Linear, CubicSpline };

struct Keyframes {
    std::vector<float> times;  // strictly increasing, finite
    std::vector<float> values; // times.size() * width values (x3 for CubicSpline)
    std::size_t width = 0;
    Interpolation interpolation = Interpolation::Linear;
    bool rotation = false; // a unit quaternion: slerp for Linear, normalised result always
};

// The sampler's value at time t (width values). Before the first key it holds the first key's
// value, after the last the last's (glTF: clamped, no extrapolation). STEP holds key k's value
// on [t_k, t_k+1). LINEAR interpolates; for rotations it slerps along the shorter arc (q and
// -q are the same rotation). CUBICSPLINE is the cubic Hermite spline whose tangents are
// multiplied by the interval's length t_k+1 - t_k, as glTF defines.
std::vector<double> sample(const Keyframes& keys, double t);

// Spherical interpolation from a to b (unit quaternions) along the shorter of the two arcs,
// normalised; nearly equal quaternions fall back to a normalised lerp.
glm::dquat slerpShortest(glm::dquat a, glm::dquat b, double u);

} // namespace wf::anim
