// MikkTSpace's steps for triangles, in its order: join corners by value; drop faces with two
// equal positions; per face the direction of dP/ds and the UV orientation (faces whose UVs span
// no area may join any neighbour, "group with any"); group the faces around each joined vertex
// that are connected through shared edges and have one orientation; per group the
// angle-weighted sum of dP/ds projected into the vertex normal's plane. With the default
// 180-degree angular threshold a group is never split further (MikkTSpace splits only faces
// whose projected tangents point exactly opposite), so one frame per group is its answer.
#include "scene/gltf/tangent_generation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include <glm/geometric.hpp>

namespace wf {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool notZero(float x) { return std::abs(x) > std::numeric_limits<float>::min(); }

// Unit length where it has a length; unchanged (zero) where not, as MikkTSpace's NormalizeSafe.
glm::vec3 normalizeSafe(const glm::vec3& v) {
    const float length = glm::length(v);
    return length > 0.0f ? v / length : v;
}

glm::vec3 project(const glm::vec3& v, const glm::vec3& n) {
    return normalizeSafe(v - n * glm::dot(n, v));
}

// A unit vector orthogonal to n (Duff et al. 2017), for corners that no usable face reaches.
glm::vec3 anyTangent(glm::vec3 n) {
    if (!finite(n) || !(glm::dot(n, n) > 0.0f))
        return glm::vec3(1.0f, 0.0f, 0.0f);
    n = glm::normalize(n);
    const float s = std::copysign(1.0f, n.z);
    const float a = -1.0f / (s + n.z);
    return glm::vec3(1.0f + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x);
}

// The bits a corner is joined by: position, normal, UV, with -0 as +0 (MikkTSpace compares
// floats, for which they are equal).
std::array<uint32_t, 8> cornerBits(const TangentCorners& in, size_t c) {
    const float values[8] = {in.positions[c].x, in.positions[c].y, in.positions[c].z,
                             in.normals[c].x,   in.normals[c].y,   in.normals[c].z,
                             in.uvs[c].x,       in.uvs[c].y};
    std::array<uint32_t, 8> bits;
    for (int k = 0; k < 8; ++k) {
        const float v = values[k] + 0.0f;
        std::memcpy(&bits[k], &v, 4);
    }
    return bits;
}

// Corners with equal bits share an id (the first such corner). Sorted by a 64-bit hash of the
// bits, then compared within runs of equal hashes: 12 bytes a corner, where a hash map of the
// bits took 3-4 times the memory on meshes of millions of triangles.
std::vector<uint32_t> joinCorners(const TangentCorners& in) {
    const size_t n = in.positions.size();
    std::vector<std::pair<uint64_t, uint32_t>> order(n);
    for (size_t c = 0; c < n; ++c) {
        uint64_t h = 1469598103934665603ull; // FNV-1a over the words, then a final mix
        for (uint32_t word : cornerBits(in, c))
            h = (h ^ word) * 1099511628211ull;
        h ^= h >> 29;
        order[c] = {h * 0xbf58476d1ce4e5b9ull, uint32_t(c)};
    }
    std::sort(order.begin(), order.end());
    std::vector<uint32_t> id(n), distinct;
    for (size_t start = 0; start < n;) {
        size_t end = start + 1;
        while (end < n && order[end].first == order[start].first)
            ++end;
        distinct.clear(); // the run's first corner of each distinct key (almost always one)
        for (size_t i = start; i < end; ++i) {
            const uint32_t c = order[i].second;
            const std::array<uint32_t, 8> bits = cornerBits(in, c);
            id[c] = c;
            for (uint32_t first : distinct) {
                if (cornerBits(in, first) == bits) {
                    id[c] = first;
                    break;
                }
            }
            if (id[c] == c)
                distinct.push_back(c);
        }
        start = end;
    }
    return id;
}

struct Face {
    glm::vec3 os{0.0f};       // unit dP/ds
    bool preserving = false;  // the UV mapping keeps the winding (signed UV area > 0)
    bool groupWithAny = true; // no usable UV mapping: joins the neighbours' frame
    bool degenerate = false;  // two equal positions: copies a twin corner's frame
    uint32_t neighbour[3] = {kNone, kNone, kNone}; // across edge (k, k+1)
};

std::vector<Face> faceFrames(const TangentCorners& in, const std::vector<uint32_t>& id) {
    std::vector<Face> faces(in.positions.size() / 3);
    for (size_t f = 0; f < faces.size(); ++f) {
        const glm::vec3* p = &in.positions[3 * f];
        const glm::vec2* t = &in.uvs[3 * f];
        Face& face = faces[f];
        face.degenerate = p[0] == p[1] || p[0] == p[2] || p[1] == p[2];
        const glm::vec3 d1 = p[1] - p[0], d2 = p[2] - p[0];
        const glm::vec2 t1 = t[1] - t[0], t2 = t[2] - t[0];
        const float area = t1.x * t2.y - t1.y * t2.x; // twice the signed UV area
        const glm::vec3 os = t2.y * d1 - t1.y * d2;   // dP/ds times area
        const glm::vec3 ot = t1.x * d2 - t2.x * d1;
        face.preserving = area > 0.0f;
        if (!notZero(area) || !std::isfinite(area) || !finite(os) || !finite(ot))
            continue;
        const float lengthS = glm::length(os), lengthT = glm::length(ot);
        const float sign = face.preserving ? 1.0f : -1.0f;
        if (notZero(lengthS))
            face.os = os * (sign / lengthS);
        face.groupWithAny =
            !(notZero(lengthS / std::abs(area)) && notZero(lengthT / std::abs(area)));
    }
    // Pair each edge with one edge running the other way between the same joined corners:
    // edges sorted by (from, to); each key's run keeps a cursor past its matched entries, so a
    // hostile edge shared by a million faces costs linear time.
    struct Edge {
        uint64_t key;     // from << 32 | to
        uint32_t corner;  // 3 f + k: edge (k, k + 1) of face f
        bool operator<(const Edge& o) const {
            return key != o.key ? key < o.key : corner < o.corner;
        }
    };
    std::vector<Edge> edges;
    edges.reserve(faces.size() * 3);
    auto key = [](uint32_t a, uint32_t b) { return uint64_t(a) << 32 | b; };
    for (size_t f = 0; f < faces.size(); ++f)
        if (!faces[f].degenerate)
            for (uint32_t k = 0; k < 3; ++k)
                edges.push_back({key(id[3 * f + k], id[3 * f + (k + 1) % 3]), uint32_t(3 * f + k)});
    std::sort(edges.begin(), edges.end());
    std::vector<uint32_t> cursor(edges.size()); // per run start: first entry not yet matched
    for (size_t i = 0; i < edges.size(); ++i)
        cursor[i] = uint32_t(i);
    for (size_t f = 0; f < faces.size(); ++f) {
        for (uint32_t k = 0; k < 3 && !faces[f].degenerate; ++k) {
            if (faces[f].neighbour[k] != kNone)
                continue;
            const uint64_t reverse = key(id[3 * f + (k + 1) % 3], id[3 * f + k]);
            const auto run = std::lower_bound(edges.begin(), edges.end(), Edge{reverse, 0});
            if (run == edges.end() || run->key != reverse)
                continue;
            uint32_t& next = cursor[size_t(run - edges.begin())];
            while (next < edges.size() && edges[next].key == reverse &&
                   faces[edges[next].corner / 3].neighbour[edges[next].corner % 3] != kNone)
                ++next;
            if (next < edges.size() && edges[next].key == reverse && edges[next].corner / 3 != f) {
                const uint32_t other = edges[next].corner;
                faces[f].neighbour[k] = other / 3;
                faces[other / 3].neighbour[other % 3] = uint32_t(f);
            }
        }
    }
    return faces;
}

// Angle at corner k of face f between its two edges, both projected into n's plane.
float cornerAngle(const TangentCorners& in, size_t f, uint32_t k, const glm::vec3& n) {
    const glm::vec3& p = in.positions[3 * f + k];
    const glm::vec3 toPrevious = project(in.positions[3 * f + (k + 2) % 3] - p, n);
    const glm::vec3 toNext = project(in.positions[3 * f + (k + 1) % 3] - p, n);
    return std::acos(glm::clamp(glm::dot(toPrevious, toNext), -1.0f, 1.0f));
}

} // namespace

std::vector<glm::vec4> generateTangents(const TangentCorners& in) {
    const size_t corners = in.positions.size() / 3 * 3;
    const std::vector<uint32_t> id = joinCorners(in);
    std::vector<Face> faces = faceFrames(in, id);
    std::vector<uint32_t> group(corners, kNone); // per corner
    std::vector<glm::vec4> frames;               // per group
    std::vector<uint32_t> members, stack;
    for (size_t f = 0; f < faces.size(); ++f) {
        for (uint32_t k = 0; k < 3; ++k) {
            if (faces[f].degenerate || faces[f].groupWithAny || group[3 * f + k] != kNone)
                continue;
            // The faces around joined corner `vertex` reached through shared edges without
            // crossing a change of orientation; group-with-any faces take the first group's.
            const uint32_t g = uint32_t(frames.size()), vertex = id[3 * f + k];
            const bool preserving = faces[f].preserving;
            members.clear();
            stack.assign(1, uint32_t(f));
            while (!stack.empty()) {
                const uint32_t h = stack.back();
                stack.pop_back();
                uint32_t j = 0;
                while (j < 3 && id[3 * h + j] != vertex)
                    ++j;
                if (j == 3 || group[3 * h + j] != kNone)
                    continue;
                Face& face = faces[h];
                if (face.groupWithAny && group[3 * h] == kNone && group[3 * h + 1] == kNone &&
                    group[3 * h + 2] == kNone)
                    face.preserving = preserving;
                if (face.preserving != preserving)
                    continue;
                group[3 * h + j] = g;
                members.push_back(3 * h + j);
                for (uint32_t next : {face.neighbour[j], face.neighbour[(j + 2) % 3]})
                    if (next != kNone)
                        stack.push_back(next);
            }
            const glm::vec3 n = in.normals[3 * f + k];
            glm::vec3 sum(0.0f);
            for (uint32_t c : members) {
                if (!faces[c / 3].groupWithAny)
                    sum += cornerAngle(in, c / 3, c % 3, n) * project(faces[c / 3].os, n);
            }
            glm::vec3 t = normalizeSafe(sum);
            if (!finite(t) || !(glm::dot(t, t) > 0.5f))
                t = anyTangent(n);
            frames.emplace_back(t, preserving ? 1.0f : -1.0f);
        }
    }
    std::vector<glm::vec4> out(corners);
    std::vector<uint32_t> healthy(corners, kNone); // joined id -> first corner of a kept face
    for (size_t c = 0; c < corners; ++c) {
        out[c] = group[c] != kNone ? frames[group[c]] : glm::vec4(anyTangent(in.normals[c]), 1.0f);
        if (!faces[c / 3].degenerate && healthy[id[c]] == kNone)
            healthy[id[c]] = uint32_t(c);
    }
    for (size_t c = 0; c < corners; ++c)
        if (faces[c / 3].degenerate && healthy[id[c]] != kNone)
            out[c] = out[healthy[id[c]]];
    return out;
}

} // namespace wf
