// Morph targets and linear blend skinning (glTF 2.0 sections 3.7.2.2 and 3.7.3).
#include "scene/animation/deformation.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

namespace wf::anim {

void applyMorphTargets(std::vector<float>& values, const std::vector<const float*>& deltas,
                       const std::vector<double>& weights) {
    for (std::size_t t = 0; t < deltas.size() && t < weights.size(); ++t) {
        if (!deltas[t] || weights[t] == 0.0)
            continue;
        const double w = weights[t];
        for (std::size_t i = 0; i < values.size(); ++i)
            values[i] = float(double(values[i]) + w * double(deltas[t][i]));
    }
}

glm::dmat4 skinMatrix(const std::vector<glm::dmat4>& jointMatrices, const float* joints,
                      const float* weights, std::size_t count) {
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i)
        sum += weights[i];
    if (!(sum > 0.0) || !std::isfinite(sum))
        return glm::dmat4(1.0);
    glm::dmat4 m(0.0);
    for (std::size_t i = 0; i < count; ++i)
        if (weights[i] != 0.0f)
            m += jointMatrices[std::size_t(joints[i])] * (double(weights[i]) / sum);
    return m;
}

void skinVertices(const std::vector<glm::dmat4>& jointMatrices, const float* joints,
                  const float* weights, std::size_t influences, std::size_t count,
                  float* positions, float* normals, float* tangents) {
    for (std::size_t v = 0; v < count; ++v) {
        const glm::dmat4 m =
            skinMatrix(jointMatrices, joints + v * influences, weights + v * influences,
                       influences);
        float* p = positions + 3 * v;
        const glm::dvec4 moved = m * glm::dvec4(p[0], p[1], p[2], 1.0);
        p[0] = float(moved.x), p[1] = float(moved.y), p[2] = float(moved.z);
        const glm::dmat3 linear(m);
        if (normals) {
            // A singular blend (joints scaled to zero) has no inverse; the normal is then left
            // for the loader's flat fallback (a zero normal).
            float* n = normals + 3 * v;
            const double det = glm::determinant(linear);
            const glm::dvec3 r = det != 0.0 && std::isfinite(det)
                                     ? glm::inverseTranspose(linear) * glm::dvec3(n[0], n[1], n[2])
                                     : glm::dvec3(0.0);
            n[0] = float(r.x), n[1] = float(r.y), n[2] = float(r.z);
        }
        if (tangents) {
            float* t = tangents + 4 * v;
            const glm::dvec3 r = linear * glm::dvec3(t[0], t[1], t[2]);
            t[0] = float(r.x), t[1] = float(r.y), t[2] = float(r.z);
        }
    }
}

} // namespace wf::anim
