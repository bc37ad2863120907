// Sampling glTF animation curves (glTF 2.0, Appendix C: interpolation).
#include "scene/animation/keyframes.h"

#include <algorithm>
#include <cmath>

namespace wf::anim {

glm::dquat slerpShortest(glm::dquat a, glm::dquat b, double u) {
    double cosTheta = glm::dot(a, b);
    if (cosTheta < 0.0) { // -b is the same rotation, and nearer
        b = -b;
        cosTheta = -cosTheta;
    }
    glm::dquat q;
    if (cosTheta > 1.0 - 1e-9) {
        q = a * (1.0 - u) + b * u; // sin(theta) ~ 0: the arc is a line
    } else {
        const double theta = std::acos(std::min(cosTheta, 1.0));
        const double s = std::sin(theta);
        q = a * (std::sin((1.0 - u) * theta) / s) + b * (std::sin(u * theta) / s);
    }
    return glm::normalize(q);
}

namespace {

glm::dquat quatAt(const float* v) { return glm::dquat(v[3], v[0], v[1], v[2]); } // w, x, y, z

std::vector<double> normalisedIfRotation(std::vector<double> out, bool rotation) {
    if (!rotation)
        return out;
    const double len = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2] +
                                 out[3] * out[3]);
    if (len > 0.0 && std::isfinite(len))
        for (double& x : out)
            x /= len;
    return out;
}

} // namespace

std::vector<double> sample(const Keyframes& keys, double t) {
    const std::size_t n = keys.times.size(), w = keys.width;
    const bool cubic = keys.interpolation == Interpolation::CubicSpline;
    // Key k's value starts at this offset (the middle of the three groups when cubic).
    auto value = [&](std::size_t k) { return keys.values.data() + (cubic ? 3 * k + 1 : k) * w; };
    auto copy = [&](const float* v) {
        return normalisedIfRotation(std::vector<double>(v, v + w), keys.rotation);
    };
    if (n == 0)
        return std::vector<double>(w, 0.0);
    if (!(t > keys.times.front()))
        return copy(value(0));
    if (t >= keys.times.back())
        return copy(value(n - 1));
    // The interval [t_k, t_k+1) holding t.
    const std::size_t k =
        std::size_t(std::upper_bound(keys.times.begin(), keys.times.end(), float(t)) -
                    keys.times.begin()) - 1;
    const double t0 = keys.times[k], t1 = keys.times[k + 1], dt = t1 - t0;
    const double u = std::clamp((t - t0) / dt, 0.0, 1.0);
    if (keys.interpolation == Interpolation::Step)
        return copy(value(k));
    std::vector<double> out(w);
    if (!cubic) {
        const float *a = value(k), *b = value(k + 1);
        if (keys.rotation) {
            const glm::dquat q = slerpShortest(quatAt(a), quatAt(b), u);
            return {q.x, q.y, q.z, q.w};
        }
        for (std::size_t i = 0; i < w; ++i)
            out[i] = a[i] + (b[i] - a[i]) * u;
        return out;
    }
    // Hermite basis; the out-tangent of k and the in-tangent of k+1 scaled by dt.
    const double u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
                 h11 = u3 - u2;
    const float* v0 = value(k);
    const float* out0 = v0 + w;                     // out-tangent of key k
    const float* v1 = value(k + 1);
    const float* in1 = v1 - w;                      // in-tangent of key k+1
    for (std::size_t i = 0; i < w; ++i)
        out[i] = h00 * v0[i] + h10 * dt * out0[i] + h01 * v1[i] + h11 * dt * in1[i];
    return normalisedIfRotation(std::move(out), keys.rotation);
}

} // namespace wf::anim
