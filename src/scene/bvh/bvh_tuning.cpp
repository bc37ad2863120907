#include "scene/bvh/bvh_tuning.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>

#include "scene/bvh/bvh_cpu.h"
#include "shaders/traversal/geometry.h"
#include "shaders/sampling/sampling.h"

namespace wf {
namespace {

using glm::vec2;
using glm::vec3;

constexpr std::uint32_t kLanes = 8;

// A step (pair fetch, two box tests, the stack) against one triangle-loop iteration (triangle
// fetch, Moller-Trumbore): fitted to callgrind's instruction counts of the intersect and shadow
// passes on lavapipe, traversal costs 1-3 on the Cornell box and the 10^2-10^5-triangle scaling
// scenes (README, Performance).
constexpr double kStepCost = 2.0;

// Random points on the emissive triangles, area-weighted.
class EmitterSampler {
public:
    EmitterSampler(const std::vector<Triangle>& triangles, const std::vector<Material>& materials)
        : triangles_(triangles) {
        double sum = 0.0;
        for (std::size_t i = 0; i < triangles.size(); ++i) {
            const Triangle& t = triangles[i];
            const bool emits = t.material < materials.size() &&
                               glm::any(glm::greaterThan(materials[t.material].emission, vec3(0)));
            if (!emits)
                continue;
            sum += 0.5 * glm::length(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
            cumulative_.push_back(sum);
            index_.push_back(i);
        }
    }

    bool empty() const { return cumulative_.empty() || !(cumulative_.back() > 0.0); }

    vec3 sample(std::mt19937& rng) const {
        std::uniform_real_distribution<double> pick(0.0, cumulative_.back());
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        const std::size_t k = std::min<std::size_t>(
            std::upper_bound(cumulative_.begin(), cumulative_.end(), pick(rng)) -
                cumulative_.begin(),
            cumulative_.size() - 1);
        const Triangle& t = triangles_[index_[k]];
        const vec2 b = gpu_types::sampleUniformTriangle(vec2(u(rng), u(rng)));
        return gpu_types::triangleHitPoint(t.p0, t.p1, t.p2, b.x, b.y);
    }

private:
    const std::vector<Triangle>& triangles_;
    std::vector<double> cumulative_;
    std::vector<std::size_t> index_;
};

// Adds the work of one batch of rays traced together, from each ray's tests per step.
void addBatch(const std::vector<std::vector<std::uint32_t>>& lanes, std::size_t count,
              SimdTraversalWork& work) {
    std::size_t steps = 0;
    for (std::size_t l = 0; l < count; ++l)
        steps = std::max(steps, lanes[l].size());
    for (std::size_t i = 0; i < steps; ++i) {
        std::uint32_t busiest = 1; // the loop body runs once even when no lane has a leaf
        for (std::size_t l = 0; l < count; ++l)
            if (i < lanes[l].size())
                busiest = std::max(busiest, lanes[l][i]);
        work.steps += 1.0;
        work.triangleIterations += busiest;
    }
}

struct Ray {
    vec3 origin;
    vec3 direction;
};

} // namespace

double SimdTraversalWork::cost() const { return kStepCost * steps + triangleIterations; }

SimdTraversalWork simdTraversalWork(const std::vector<BvhNode>& nodes,
                                    const std::vector<Triangle>& triangles,
                                    const std::vector<Material>& materials, const Camera& camera,
                                    std::uint32_t side, std::uint32_t seed) {
    SimdTraversalWork work;
    if (triangles.empty() || side == 0)
        return work;
    const CpuBvh bvh(nodes, triangles);
    const EmitterSampler emitters(triangles, materials);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);

    std::vector<Ray> queue;
    const vec3 right = glm::normalize(glm::cross(camera.forward, camera.up));
    const float tanHalf = std::tan(0.5f * camera.yfov);
    for (std::uint32_t y = 0; y < side; ++y)
        for (std::uint32_t x = 0; x < side; ++x) {
            const float sx = (2.0f * (float(x) + u(rng)) / float(side) - 1.0f) * tanHalf;
            const float sy = (1.0f - 2.0f * (float(y) + u(rng)) / float(side)) * tanHalf;
            queue.push_back({camera.position,
                             glm::normalize(camera.forward + sx * right + sy * camera.up)});
        }
    std::vector<std::vector<std::uint32_t>> closest(kLanes), shadow(kLanes);
    for (int depth = 0; depth < 4 && !queue.empty(); ++depth) {
        std::vector<Ray> next;
        for (std::size_t first = 0; first < queue.size(); first += kLanes) {
            const std::size_t count = std::min<std::size_t>(kLanes, queue.size() - first);
            std::size_t shadows = 0;
            for (std::size_t l = 0; l < count; ++l) {
                const Ray& ray = queue[first + l];
                HitRecord hit;
                closest[l].clear();
                if (!bvh.traceClosest(ray.origin, ray.direction, 3.0e38f, hit, &closest[l]))
                    continue;
                const Triangle& t = triangles[hit.triangle];
                const vec3 p = gpu_types::triangleHitPoint(t.p0, t.p1, t.p2, hit.b1, hit.b2);
                const vec3 error = gpu_types::triangleSpawnError(t.p0, t.p1, t.p2, hit.b1, hit.b2);
                vec3 n = glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0));
                if (glm::dot(n, ray.direction) > 0.0f)
                    n = -n; // the side the ray arrived from
                if (!emitters.empty()) {
                    const vec3 q = emitters.sample(rng);
                    const vec3 from = gpu_types::offsetRayOrigin(p, error, n, q - p);
                    shadow[shadows].clear();
                    bvh.traceAny(from, q - from, 0.999f, &shadow[shadows]);
                    ++shadows;
                }
                const vec3 local = gpu_types::sampleCosineHemisphere(vec2(u(rng), u(rng)));
                vec3 tangent, bitangent;
                gpu_types::buildOrthonormalBasis(n, tangent, bitangent);
                const vec3 d = tangent * local.x + bitangent * local.y + n * local.z;
                next.push_back({gpu_types::offsetRayOrigin(p, error, n, d), d});
            }
            addBatch(closest, count, work);
            addBatch(shadow, shadows, work);
        }
        queue = std::move(next);
    }
    return work;
}

BvhBuildStats buildTunedBvh(std::vector<Triangle>& triangles, std::vector<BvhNode>& nodes,
                            const std::vector<Material>& materials, const Camera& camera) {
    BvhBuildOptions options;
    options.traversalCost = kTunedTraversalCosts[0];
    if (triangles.size() > kMaxTunedTriangles) {
        BvhBuildStats stats = buildBvh(triangles, nodes, options);
        stats.traversalCost = options.traversalCost;
        return stats;
    }
    // Scenes this small build in milliseconds: every node gets every bin, which keeps their
    // trees (chosen per scene by the model below) as they were measured.
    options.fewerBinsForSmallNodes = false;
    const auto start = std::chrono::steady_clock::now();
    const std::vector<Triangle> input = triangles;
    BvhBuildStats best;
    double bestCost = std::numeric_limits<double>::infinity();
    for (const float traversalCost : kTunedTraversalCosts) {
        std::vector<Triangle> candidateTriangles = input;
        std::vector<BvhNode> candidateNodes;
        options.traversalCost = traversalCost;
        const BvhBuildStats stats = buildBvh(candidateTriangles, candidateNodes, options);
        const double cost =
            simdTraversalWork(candidateNodes, candidateTriangles, materials, camera).cost();
        if (cost < bestCost) { // strictly: the first of equals stays
            bestCost = cost;
            best = stats;
            best.traversalCost = traversalCost;
            triangles = std::move(candidateTriangles);
            nodes = std::move(candidateNodes);
        }
    }
    best.buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return best;
}

} // namespace wf
