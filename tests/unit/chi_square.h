// Chi-square goodness-of-fit machinery for the sampling tests: Pearson's statistic with pooling
// of small cells, and expected counts over (cos theta, phi) cells of the sphere integrated from
// a pdf by adaptive Simpson quadrature, so that peaked lobes (GGX at alpha 0.01) are resolved.
#ifndef WF_TESTS_CHI_SQUARE_H
#define WF_TESTS_CHI_SQUARE_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numeric>
#include <random>
#include <vector>

#include <glm/glm.hpp>

namespace wf::test {

// Regularised upper incomplete gamma Q(a, x) (Numerical Recipes 6.2): series below a + 1,
// Lentz's continued fraction above.
inline double gammaQ(double a, double x) {
    if (x <= 0.0) {
        return 1.0;
    }
    double logPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 10000 && std::abs(term) > std::abs(sum) * 1e-15; ++n) {
            term *= x / (a + n);
            sum += term;
        }
        return 1.0 - sum * std::exp(logPrefix);
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        d = std::abs(d) < tiny ? tiny : d;
        c = b + an / c;
        c = std::abs(c) < tiny ? tiny : c;
        d = 1.0 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1.0) < 1e-15) {
            break;
        }
    }
    return std::exp(logPrefix) * h;
}

// Pearson's chi-square p-value. Cells expecting fewer than 5 samples are pooled (smallest
// first) so the statistic's chi-square approximation holds; a sample in a cell expecting
// none is an outright failure.
inline double chiSquarePValue(const std::vector<double>& observed,
                              const std::vector<double>& expected) {
    std::vector<size_t> order(observed.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return expected[a] < expected[b]; });
    double chi2 = 0.0, poolObs = 0.0, poolExp = 0.0;
    int cells = 0;
    for (size_t i : order) {
        if (expected[i] <= 0.0 && observed[i] > 0.0) {
            return 0.0;
        }
        poolObs += observed[i];
        poolExp += expected[i];
        if (poolExp >= 5.0) {
            chi2 += (poolObs - poolExp) * (poolObs - poolExp) / poolExp;
            ++cells;
            poolObs = poolExp = 0.0;
        }
    }
    if (poolExp > 0.0) { // leftovers too small to stand alone
        chi2 += (poolObs - poolExp) * (poolObs - poolExp) / poolExp;
        ++cells;
    }
    return cells > 1 ? gammaQ(0.5 * (cells - 1), 0.5 * chi2) : 1.0;
}

// The whole sphere cut into cosBins x phiBins cells of equal solid angle: cos theta in [-1, 1]
// (an even cosBins puts a cell edge on the horizon, where reflection meets transmission).
struct SphereGrid {
    int cosBins = 20;
    int phiBins = 40;

    size_t cells() const { return size_t(cosBins) * size_t(phiBins); }

    size_t cellOf(glm::vec3 w) const {
        double c = std::clamp(double(w.z), -1.0, 1.0);
        double phi = std::atan2(double(w.y), double(w.x));
        phi = phi < 0.0 ? phi + 2.0 * M_PI : phi;
        int ci = std::clamp(int((c + 1.0) * 0.5 * cosBins), 0, cosBins - 1);
        int pi = std::clamp(int(phi / (2.0 * M_PI) * phiBins), 0, phiBins - 1);
        return size_t(ci) * size_t(phiBins) + size_t(pi);
    }
};

// Unit vector at (cos theta, phi).
inline glm::vec3 sphereDirection(double cosTheta, double phi) {
    double s = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return glm::vec3(float(s * std::cos(phi)), float(s * std::sin(phi)), float(cosTheta));
}

namespace detail {

using Integrand = std::function<double(double, double)>;

// 3x3 Simpson rule on [x0, x1] x [y0, y1]. Points sit a hair inside the rectangle, so a pdf that
// jumps on a cell edge (the horizon, a critical angle) is read from the cell's own side.
inline double simpson2(const Integrand& f, double x0, double x1, double y0, double y1) {
    const double w[3] = {1.0, 4.0, 1.0};
    double ex = 1e-9 * (x1 - x0), ey = 1e-9 * (y1 - y0);
    double xs[3] = {x0 + ex, 0.5 * (x0 + x1), x1 - ex};
    double ys[3] = {y0 + ey, 0.5 * (y0 + y1), y1 - ey};
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            sum += w[i] * w[j] * f(xs[i], ys[j]);
        }
    }
    return sum * (x1 - x0) * (y1 - y0) / 36.0;
}

inline double adaptiveSimpson2(const Integrand& f, double x0, double x1, double y0, double y1,
                               double whole, double tolerance, int depth) {
    double xm = 0.5 * (x0 + x1), ym = 0.5 * (y0 + y1);
    double q[4] = {simpson2(f, x0, xm, y0, ym), simpson2(f, xm, x1, y0, ym),
                   simpson2(f, x0, xm, ym, y1), simpson2(f, xm, x1, ym, y1)};
    double parts = q[0] + q[1] + q[2] + q[3];
    if (depth <= 0 || std::abs(parts - whole) <= 15.0 * tolerance) {
        return parts + (parts - whole) / 15.0;
    }
    double t = 0.25 * tolerance;
    return adaptiveSimpson2(f, x0, xm, y0, ym, q[0], t, depth - 1) +
           adaptiveSimpson2(f, xm, x1, y0, ym, q[1], t, depth - 1) +
           adaptiveSimpson2(f, x0, xm, ym, y1, q[2], t, depth - 1) +
           adaptiveSimpson2(f, xm, x1, ym, y1, q[3], t, depth - 1);
}

} // namespace detail

// Integral of pdf(direction) d omega over every cell of the grid (d omega = d cos d phi). Each
// cell starts as 4x4 Simpson panels, refined where they disagree by more than `tolerance`
// (absolute, per cell) allows.
inline std::vector<double> integrateOverCells(const SphereGrid& grid,
                                              const std::function<double(glm::vec3)>& pdf,
                                              double tolerance) {
    detail::Integrand f = [&](double c, double phi) { return pdf(sphereDirection(c, phi)); };
    std::vector<double> result(grid.cells(), 0.0);
    const int panels = 4, maxDepth = 6;
    double dc = 2.0 / grid.cosBins, dp = 2.0 * M_PI / grid.phiBins;
    for (int ci = 0; ci < grid.cosBins; ++ci) {
        for (int pi = 0; pi < grid.phiBins; ++pi) {
            double sum = 0.0;
            for (int a = 0; a < panels; ++a) {
                for (int b = 0; b < panels; ++b) {
                    double x0 = -1.0 + dc * (ci + double(a) / panels);
                    double x1 = -1.0 + dc * (ci + double(a + 1) / panels);
                    double y0 = dp * (pi + double(b) / panels);
                    double y1 = dp * (pi + double(b + 1) / panels);
                    double whole = detail::simpson2(f, x0, x1, y0, y1);
                    sum += detail::adaptiveSimpson2(f, x0, x1, y0, y1, whole,
                                                    tolerance / (panels * panels), maxDepth);
                }
            }
            result[size_t(ci) * size_t(grid.phiBins) + size_t(pi)] = sum;
        }
    }
    return result;
}

// A uniform float in [0, 1): generate_canonical<float> can round to 1.0f; samplers take [0, 1).
inline float uniform01(std::mt19937& rng) {
    return std::min(std::uniform_real_distribution<float>(0.0f, 1.0f)(rng), 0x1.fffffep-1f);
}

// Counts per grid cell of `samples` directions drawn by sample(uLobe, u, wi) (false: no
// direction, or a Dirac one, whose mass the pdfs leave out too).
template <typename Sample>
std::vector<double> sampleHistogram(const SphereGrid& grid, unsigned seed, int samples,
                                    Sample sample) {
    std::mt19937 rng(seed);
    std::vector<double> counts(grid.cells(), 0.0);
    for (int i = 0; i < samples; ++i) {
        const float uLobe = uniform01(rng);
        const glm::vec2 u(uniform01(rng), uniform01(rng));
        glm::vec3 wi;
        if (sample(uLobe, u, wi))
            counts[grid.cellOf(wi)] += 1.0;
    }
    return counts;
}

// The chi-square p-value of `counts` (from `samples` draws) against pdf integrated over the
// grid's cells.
inline double pdfFitPValue(const std::vector<double>& counts, const SphereGrid& grid,
                           int samples, const std::function<double(glm::vec3)>& pdf) {
    std::vector<double> expected = integrateOverCells(grid, pdf, 0.05 / samples);
    for (double& e : expected)
        e *= samples;
    return chiSquarePValue(counts, expected);
}

} // namespace wf::test

#endif
