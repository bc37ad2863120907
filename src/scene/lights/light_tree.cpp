#include "scene/lights/light_tree.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace wf {
namespace {

// A light's or a node's bounds, in double while building.
struct LightBounds {
    glm::dvec3 lo{1e300}, hi{-1e300};
    double power = 0.0;
    glm::dvec3 axis{0.0, 0.0, 1.0};
    double thetaO = 0.0; // half-angle of the normals' cone (angles, not cosines: merges are
    double thetaE = 0.0; // hot in the build, and acos is not cheap)
    bool twoSided = false;
    glm::dvec3 centroid() const { return 0.5 * (lo + hi); }
};

double angle(double cosine) { return std::acos(std::clamp(cosine, -1.0, 1.0)); }

// The smallest cone around both (pbrt-v4's DirectionCone union).
void unionCones(const LightBounds& a, const LightBounds& b, glm::dvec3& axis, double& theta) {
    axis = a.axis;
    theta = M_PI;
    if (a.thetaO >= M_PI || b.thetaO >= M_PI)
        return;
    const double thetaA = a.thetaO, thetaB = b.thetaO;
    const double thetaD = angle(glm::dot(a.axis, b.axis));
    if (std::min(thetaD + thetaB, M_PI) <= thetaA) {
        theta = thetaA;
        return;
    }
    if (std::min(thetaD + thetaA, M_PI) <= thetaB) {
        axis = b.axis;
        theta = thetaB;
        return;
    }
    const double thetaO = 0.5 * (thetaA + thetaD + thetaB);
    const glm::dvec3 w = glm::cross(a.axis, b.axis);
    if (thetaO >= M_PI || glm::length(w) < 1e-12)
        return;
    // Turn a's axis towards b's by thetaO - thetaA (Rodrigues, about an axis normal to it).
    const double turn = thetaO - thetaA;
    const glm::dvec3 k = glm::normalize(w);
    axis = glm::normalize(a.axis * std::cos(turn) + glm::cross(k, a.axis) * std::sin(turn));
    theta = thetaO;
}

LightBounds merge(const LightBounds& a, const LightBounds& b) {
    if (!(a.power > 0.0))
        return b;
    if (!(b.power > 0.0))
        return a;
    LightBounds m;
    m.lo = glm::min(a.lo, b.lo);
    m.hi = glm::max(a.hi, b.hi);
    m.power = a.power + b.power;
    unionCones(a, b, m.axis, m.thetaO);
    m.thetaE = std::max(a.thetaE, b.thetaE);
    m.twoSided = a.twoSided || b.twoSided;
    return m;
}

// pbrt-v4's SAOH: power x the solid-angle measure of the emission cones x the box's area,
// with the box's aspect along the split axis (Kr) against long thin children.
double splitCost(const LightBounds& b, double kr) {
    if (!(b.power > 0.0))
        return 0.0;
    const double thetaO = b.thetaO, thetaE = b.thetaE;
    const double thetaW = std::min(thetaO + thetaE, M_PI);
    const double cosThetaO = std::cos(thetaO), sinThetaO = std::sin(thetaO);
    const double measure = 2.0 * M_PI * (1.0 - cosThetaO) +
                           M_PI / 2.0 *
                               (2.0 * thetaW * sinThetaO - std::cos(thetaO - 2.0 * thetaW) -
                                2.0 * thetaO * sinThetaO + cosThetaO);
    const glm::dvec3 d = b.hi - b.lo;
    const double area = 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x);
    return b.power * measure * kr * area;
}

struct Item {
    LightBounds bounds;
    uint32_t emitter;
};

class Builder {
public:
    Builder(LightTree& tree) : tree_(tree) {}

    // Builds the subtree of items[begin, end) at tree_.nodes[index]; returns its bounds.
    LightBounds build(std::vector<Item>& items, size_t begin, size_t end, uint32_t depth,
                      glm::uvec2 trail) {
        const uint32_t index = static_cast<uint32_t>(tree_.nodes.size());
        tree_.nodes.emplace_back();
        tree_.depth = std::max(tree_.depth, depth);
        if (end - begin == 1) {
            const Item& item = items[begin];
            tree_.trails[item.emitter] = glm::uvec4(trail, 1u, 0u);
            store(index, item.bounds, WF_LIGHT_TREE_LEAF | item.emitter);
            return item.bounds;
        }
        const size_t middle = split(items, begin, end, depth);
        const LightBounds first = build(items, begin, middle, depth + 1, trail);
        glm::uvec2 secondTrail = trail;
        (depth < 32 ? secondTrail.x : secondTrail.y) |= 1u << (depth & 31u);
        const uint32_t second = static_cast<uint32_t>(tree_.nodes.size());
        const LightBounds other = build(items, middle, end, depth + 1, secondTrail);
        const LightBounds bounds = merge(first, other);
        store(index, bounds, second);
        return bounds;
    }

private:
    void store(uint32_t index, const LightBounds& b, uint32_t child) {
        gpu_types::LightTreeNode& node = tree_.nodes[index];
        node.lo = glm::vec3(b.lo);
        node.hi = glm::vec3(b.hi);
        node.power = static_cast<float>(b.power);
        node.child = child;
        node.axis = glm::vec3(b.axis);
        node.cosThetaO = b.thetaO >= M_PI ? -1.0f : static_cast<float>(std::cos(b.thetaO));
        // cos(pi / 2) in double is 6e-17, not 0: a point at right angles must not be culled.
        node.cosThetaE = b.thetaE >= M_PI / 2.0 ? std::min(0.0f, float(std::cos(b.thetaE)))
                                                 : static_cast<float>(std::cos(b.thetaE));
        node.twoSided = b.twoSided ? 1u : 0u;
    }

    // Partitions items[begin, end) at the cheapest of 12 buckets per axis of the centroids'
    // box; deep in the tree, or where no axis separates them, at the median of the longest
    // axis, so that no trail outgrows its 64 bits.
    size_t split(std::vector<Item>& items, size_t begin, size_t end, uint32_t depth) {
        glm::dvec3 lo(1e300), hi(-1e300), boxLo(1e300), boxHi(-1e300);
        for (size_t i = begin; i < end; ++i) {
            lo = glm::min(lo, items[i].bounds.centroid());
            hi = glm::max(hi, items[i].bounds.centroid());
            boxLo = glm::min(boxLo, items[i].bounds.lo);
            boxHi = glm::max(boxHi, items[i].bounds.hi);
        }
        const glm::dvec3 extent = hi - lo, diagonal = boxHi - boxLo;
        const int longest = extent.x >= extent.y && extent.x >= extent.z ? 0
                            : extent.y >= extent.z                       ? 1
                                                                         : 2;
        auto bucketOf = [&](const Item& item, int axis) {
            const double t = (item.bounds.centroid()[axis] - lo[axis]) / extent[axis];
            return std::min(kBuckets - 1, static_cast<int>(t * kBuckets));
        };
        double bestCost = 1e300;
        int bestAxis = -1, bestBucket = 0;
        for (int axis = 0; axis < 3 && depth < kSaohDepth; ++axis) {
            if (!(extent[axis] > 0.0))
                continue;
            LightBounds buckets[kBuckets];
            for (size_t i = begin; i < end; ++i)
                buckets[bucketOf(items[i], axis)] =
                    merge(buckets[bucketOf(items[i], axis)], items[i].bounds);
            const double maxDiagonal = std::max({diagonal.x, diagonal.y, diagonal.z});
            const double kr = diagonal[axis] > 0.0 ? maxDiagonal / diagonal[axis] : 1.0;
            // Costs of the buckets above each split, swept from the top, then the ones below
            // swept from the bottom: two merges per bucket.
            double aboveCost[kBuckets];
            bool aboveLit[kBuckets];
            LightBounds above;
            for (int b = kBuckets - 1; b > 0; --b) {
                above = merge(above, buckets[b]);
                aboveCost[b] = splitCost(above, kr);
                aboveLit[b] = above.power > 0.0;
            }
            LightBounds below;
            for (int s = 0; s + 1 < kBuckets; ++s) {
                below = merge(below, buckets[s]);
                if (!(below.power > 0.0) || !aboveLit[s + 1])
                    continue;
                const double cost = splitCost(below, kr) + aboveCost[s + 1];
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = axis;
                    bestBucket = s;
                }
            }
        }
        if (bestAxis >= 0) {
            auto mid = std::partition(items.begin() + begin, items.begin() + end,
                                      [&](const Item& item) {
                                          return bucketOf(item, bestAxis) <= bestBucket;
                                      });
            return static_cast<size_t>(mid - items.begin());
        }
        const size_t middle = begin + (end - begin) / 2;
        std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                         [&](const Item& a, const Item& b) {
                             return a.bounds.centroid()[longest] < b.bounds.centroid()[longest];
                         });
        return middle;
    }

    static constexpr int kBuckets = 12;
    // Past this depth splits are medians: 36 + log2(2^24 lights) levels stay within 64.
    static constexpr uint32_t kSaohDepth = 36;
    LightTree& tree_;
};

LightBounds boundsOf(uint32_t source, double power, const std::vector<Triangle>& triangles,
                     const std::vector<Material>& materials,
                     const std::vector<PunctualLight>& lights) {
    LightBounds b;
    b.power = power;
    const uint32_t index = source & WF_EMITTER_INDEX_MASK;
    if ((source & WF_EMITTER_KIND_MASK) == WF_EMITTER_TRIANGLE) {
        const Triangle& tri = triangles[index];
        const glm::dvec3 p0(tri.p0), p1(tri.p1), p2(tri.p2);
        b.lo = glm::min(p0, glm::min(p1, p2));
        b.hi = glm::max(p0, glm::max(p1, p2));
        b.axis = glm::normalize(glm::cross(p1 - p0, p2 - p0));
        b.thetaO = 0.0; // one normal, emitting into its hemisphere
        b.thetaE = M_PI / 2.0;
        b.twoSided = (materials[tri.material].flags & WF_MATERIAL_DOUBLE_SIDED) != 0u;
        return b;
    }
    const PunctualLight& light = lights[index];
    const glm::dvec3 position(light.position);
    const double radius = light.type == WF_LIGHT_SPHERE ? light.radius : 0.0;
    b.lo = position - glm::dvec3(radius);
    b.hi = position + glm::dvec3(radius);
    if (light.type == WF_LIGHT_SPOT) { // light leaves the point only inside the outer cone
        b.axis = glm::normalize(glm::dvec3(light.direction));
        b.thetaO = angle(light.cosOuter);
        b.thetaE = 0.0;
    } else { // every direction
        b.thetaO = M_PI;
        b.thetaE = M_PI / 2.0;
    }
    return b;
}

} // namespace

bool inLightTree(uint32_t source, const std::vector<PunctualLight>& lights) {
    const uint32_t kind = source & WF_EMITTER_KIND_MASK;
    if (kind == WF_EMITTER_TRIANGLE)
        return true;
    return kind == WF_EMITTER_LIGHT &&
           lights[source & WF_EMITTER_INDEX_MASK].type != WF_LIGHT_DIRECTIONAL;
}

LightTree buildLightTree(const LightTable& table, const std::vector<Triangle>& triangles,
                         const std::vector<Material>& materials,
                         const std::vector<PunctualLight>& lights,
                         const std::vector<glm::vec4>& motionKeys, uint32_t motionSegments) {
    const auto start = std::chrono::steady_clock::now();
    LightTree tree;
    tree.trails.assign(table.emitters.size(), glm::uvec4(0u));
    std::vector<Item> items;
    for (uint32_t e = 0; e < table.emitters.size(); ++e) {
        const uint32_t source = table.emitters[e].source;
        if (!inLightTree(source, lights))
            continue;
        const double power = double(table.emitters[e].pmf) * table.totalPower;
        LightBounds bounds = boundsOf(source, power, triangles, materials, lights);
        const uint32_t kind = source & WF_EMITTER_KIND_MASK;
        const PunctualLight* light =
            kind == WF_EMITTER_LIGHT ? &lights[source & WF_EMITTER_INDEX_MASK] : nullptr;
        if (light && light->motion != 0u) { // light.motion: 1 + its first key
            const double radius = light->type == WF_LIGHT_SPHERE ? light->radius : 0.0;
            for (uint32_t k = 0; k <= motionSegments; ++k) {
                const glm::dvec3 p(glm::vec3(motionKeys.at(light->motion - 1u + k)));
                bounds.lo = glm::min(bounds.lo, p - glm::dvec3(radius));
                bounds.hi = glm::max(bounds.hi, p + glm::dvec3(radius));
            }
        }
        items.push_back({std::move(bounds), e});
        tree.power += power;
    }
    tree.lights = static_cast<uint32_t>(items.size());
    if (!items.empty()) {
        tree.nodes.reserve(2 * items.size() - 1);
        Builder(tree).build(items, 0, items.size(), 0, glm::uvec2(0u));
    }
    tree.buildSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return tree;
}

} // namespace wf
