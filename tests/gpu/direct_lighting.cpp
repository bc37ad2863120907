#include "direct_lighting.h"

#include <algorithm>
#include <cmath>

namespace wf::test {

double sphereIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 center, double radius,
                        double radiance) {
    const double d = glm::length(center - p);
    if (d <= radius)
        return 0.0;
    const double sin2Alpha = (radius / d) * (radius / d);
    const double cosTheta = std::clamp(glm::dot(n, (center - p) / d), -1.0, 1.0);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    // Whole cap above the horizon: cos theta >= sin alpha; whole cap below: <= -sin alpha.
    if (cosTheta * cosTheta >= sin2Alpha)
        return cosTheta > 0.0 ? M_PI * radiance * sin2Alpha * cosTheta : 0.0;
    const double x = std::sqrt(1.0 / sin2Alpha - 1.0); // cot alpha
    const double y = -x * cosTheta / sinTheta;         // where the horizon cuts the cap
    const double s = sinTheta * std::sqrt(std::max(0.0, 1.0 - y * y));
    return radiance * ((cosTheta * std::acos(std::clamp(y, -1.0, 1.0)) - x * s) * sin2Alpha +
                       std::atan(s / x));
}

double polygonIrradiance(glm::dvec3 p, glm::dvec3 n, const glm::dvec3* vertices, int count,
                         double radiance) {
    const glm::dvec3 front =
        glm::cross(vertices[1] - vertices[0], vertices[count - 1] - vertices[0]);
    if (glm::dot(front, p - vertices[0]) <= 0.0)
        return 0.0; // behind a one-sided emitter, or in its plane
    // Sutherland-Hodgman against p's horizon plane, on vectors from p: a convex polygon keeps
    // at most one vertex more.
    glm::dvec3 clipped[kMaxPolygonVertices + 1];
    int kept = 0;
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 a = vertices[i] - p, b = vertices[(i + 1) % count] - p;
        const double ha = glm::dot(n, a), hb = glm::dot(n, b);
        if (ha >= 0.0)
            clipped[kept++] = a;
        if ((ha >= 0.0) != (hb >= 0.0))
            clipped[kept++] = a + (b - a) * (ha / (ha - hb));
    }
    double sum = 0.0;
    for (int i = 0; i < kept; ++i) {
        const glm::dvec3 a = glm::normalize(clipped[i]);
        const glm::dvec3 b = glm::normalize(clipped[(i + 1) % kept]);
        const glm::dvec3 c = glm::cross(a, b);
        const double sinAngle = glm::length(c);
        if (sinAngle > 0.0)
            sum += std::atan2(sinAngle, glm::dot(a, b)) * glm::dot(n, c / sinAngle);
    }
    return 0.5 * radiance * std::abs(sum);
}

double pointIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 position, double intensity) {
    const glm::dvec3 toLight = position - p;
    const double d2 = glm::dot(toLight, toLight);
    return intensity * std::max(0.0, glm::dot(n, toLight)) / (d2 * std::sqrt(d2));
}

double spotIrradiance(glm::dvec3 p, glm::dvec3 n, glm::dvec3 position, glm::dvec3 direction,
                      double cosInner, double cosOuter, double intensity) {
    const double cosAngle = glm::dot(glm::normalize(p - position), direction);
    const double x =
        std::clamp((cosAngle - cosOuter) / std::max(cosInner - cosOuter, 1e-4), 0.0, 1.0);
    return x * x * pointIrradiance(p, n, position, intensity);
}

double directionalIrradiance(glm::dvec3 n, glm::dvec3 direction, double illuminance) {
    return illuminance * std::max(0.0, -glm::dot(n, direction));
}

} // namespace wf::test
