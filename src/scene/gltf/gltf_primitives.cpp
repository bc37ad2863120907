// Primitive assembly. Attributes are looked up per corner through the same vertex index as the
// position, so indexed, non-indexed, strip and fan primitives share one loop.
#include "scene/gltf/gltf_primitives.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

#include <glm/gtc/packing.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include "scene/gltf/gltf_scene_limits.h"
#include "scene/gltf/tangent_generation.h"

namespace wf::gltf {

namespace {

// The GPU normalizes cross(p1 - p0, p2 - p0) in float; a triangle whose float cross product
// has no normal-range squared length (too small, or overflowing to infinity for coordinates
// near 1e19) would give it a NaN normal, so such triangles count as degenerate.
bool isDegenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    const float length2 = glm::dot(n, n);
    return !(length2 >= std::numeric_limits<float>::min() &&
             length2 <= std::numeric_limits<float>::max());
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x + v.y + v.z); }

// Position i takes element order[i], in place, one cycle of the permutation at a time: a
// permuted copy of millions of triangles would be the peak of host memory. `order` is taken
// by value, as it marks the positions placed. Empty arrays stay empty.
template <typename T> void permuteInPlace(std::vector<T>& array, std::vector<uint32_t> order) {
    if (array.empty())
        return;
    for (size_t first = 0; first < order.size(); ++first) {
        if (order[first] == first)
            continue;
        const T carried = array[first];
        size_t i = first;
        for (;;) {
            const size_t from = order[i];
            order[i] = uint32_t(i);
            if (from == first) {
                array[i] = carried;
                break;
            }
            array[i] = array[from];
            i = from;
        }
    }
}

// Any unit vector orthogonal to n (Duff et al. 2017).
glm::vec3 orthogonal(const glm::vec3& n) {
    const float s = std::copysign(1.0f, n.z);
    const float a = -1.0f / (s + n.z);
    return glm::vec3(1.0f + s * n.x * n.x * a, s * n.x * n.y * a, -s * n.x);
}

// MikkTSpace frames for a primitive without TANGENT, per corner of `order`, in the primitive's
// own space (before any node transform, so every placement of a mesh gets the same frames).
// glTF's v runs down the image; MikkTSpace's t runs up, so it reads (u, -v).
std::vector<glm::vec4> mikkTangents(const FloatArray& points, const FloatArray* normals,
                                    const FloatArray* uvs, const std::vector<uint32_t>& order) {
    TangentCorners corners;
    corners.positions.resize(order.size());
    corners.normals.resize(order.size());
    corners.uvs.resize(order.size(), glm::vec2(0.0f));
    for (size_t c = 0; c < order.size(); ++c) {
        const float* q = points[order[c]];
        corners.positions[c] = glm::vec3(q[0], q[1], q[2]);
        if (uvs)
            corners.uvs[c] = glm::vec2((*uvs)[order[c]][0], -(*uvs)[order[c]][1]);
    }
    for (size_t t = 0; t + 2 < order.size(); t += 3) {
        const glm::vec3* p = &corners.positions[t];
        const glm::vec3 face = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        for (size_t k = 0; k < 3; ++k) {
            glm::vec3 n = face;
            if (normals) {
                const float* q = (*normals)[order[t + k]];
                const glm::vec3 given = glm::normalize(glm::vec3(q[0], q[1], q[2]));
                n = finite(given) ? given : face;
            }
            corners.normals[t + k] = n;
        }
    }
    return generateTangents(corners);
}

} // namespace

uint32_t octEncode(glm::vec3 n) {
    const float sum = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    if (!(sum > 0.0f && sum <= std::numeric_limits<float>::max())) {
        return glm::packSnorm2x16(glm::vec2(0.0f)); // +Z; callers pass unit vectors
    }
    n /= sum;
    glm::vec2 e(n.x, n.y);
    if (n.z < 0.0f) {
        e = glm::vec2((1.0f - std::abs(n.y)) * (n.x >= 0.0f ? 1.0f : -1.0f),
                      (1.0f - std::abs(n.x)) * (n.y >= 0.0f ? 1.0f : -1.0f));
    }
    return glm::packSnorm2x16(e);
}

PrimitiveBuilder::PrimitiveBuilder(const tinygltf::Model& model, const std::string& file,
                                   const MaterialTables& materials, uint32_t defaultMaterial)
    : model_(model), file_(file), materials_(materials), defaultMaterial_(defaultMaterial),
      reader_(model, file) {}

std::vector<uint32_t> PrimitiveBuilder::corners(int mode, size_t vertexCount, int indices,
                                                const std::string& where) {
    const std::vector<uint32_t> order =
        indices != -1 ? reader_.indices(indices, vertexCount, where) : std::vector<uint32_t>{};
    const size_t n = indices != -1 ? order.size() : vertexCount;
    auto v = [&](size_t i) { return indices != -1 ? order[i] : uint32_t(i); };
    if (mode == TINYGLTF_MODE_TRIANGLES && n % 3 != 0) {
        fail(file_, where + ": " + std::to_string(n) + " vertices do not make whole triangles");
    }
    const size_t triangles = trianglesOfPrimitive(mode, n);
    if (triangles > maxSceneTriangles() - triangles_.size()) {
        fail(file_, "more than " + std::to_string(maxSceneTriangles()) + " triangles, " +
                        sceneTriangleLimitReason());
    }
    std::vector<uint32_t> out;
    out.reserve(triangles * 3);
    for (size_t i = 0; i < triangles; ++i) {
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            out.insert(out.end(), {v(3 * i), v(3 * i + 1), v(3 * i + 2)});
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) { // every other one flipped back
            out.insert(out.end(), {v(i), v(i + 1 + i % 2), v(i + 2 - i % 2)});
        } else { // fan
            out.insert(out.end(), {v(i + 1), v(i + 2), v(0)});
        }
    }
    return out;
}

void PrimitiveBuilder::add(const tinygltf::Primitive& primitive, const std::string& where,
                           const glm::dmat4& world, uint32_t mesh,
                           const Deformation* deformation) {
    if (mesh != kWorldGeometry && !grouping_) {
        meshOf_.assign(triangles_.size(), kWorldGeometry);
        grouping_ = true;
    }
    const int mode = primitive.mode;
    if (mode >= TINYGLTF_MODE_POINTS && mode <= TINYGLTF_MODE_LINE_STRIP) {
        ++skippedPrimitives_;
        return;
    }
    if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        mode != TINYGLTF_MODE_TRIANGLE_FAN) {
        fail(file_, where + ": mode " + std::to_string(mode) + " is not a glTF primitive mode");
    }
    if (const int empty = accessorWithoutData(model_, primitive); empty != -1) {
        gltf::warn(file_, where + " skipped: its accessor " + std::to_string(empty) +
                              " reads a buffer without data (no uri; glTF leaves such buffers to "
                              "extensions)");
        return;
    }
    auto attribute = [&](const char* key) {
        auto found = primitive.attributes.find(key);
        return found == primitive.attributes.end() ? -1 : found->second;
    };
    if (attribute("POSITION") == -1) {
        fail(file_, where + " has no POSITION attribute");
    }
    const FloatArray* points = &reader_.floats(attribute("POSITION"), "POSITION of " + where, 3);
    uint32_t material = defaultMaterial_;
    MaterialNeeds needs;
    if (primitive.material == -1) {
        usedDefault_ = true;
    } else {
        checkIndex(file_, primitive.material, materials_.materials.size(), "material", where);
        material = uint32_t(primitive.material);
        needs = materials_.needs[material];
    }
    // Optional attributes must have one element per vertex.
    auto optional = [&](const char* key, int components, bool wanted) -> const FloatArray* {
        if (!wanted || attribute(key) == -1) {
            return nullptr;
        }
        const FloatArray& array =
            reader_.floats(attribute(key), std::string(key) + " of " + where, components);
        if (array.count != points->count) {
            fail(file_, where + ": " + key + " has " + std::to_string(array.count) +
                            " elements but POSITION has " + std::to_string(points->count));
        }
        return &array;
    };
    const FloatArray* normals = optional("NORMAL", 3, true);
    // Tangent frames follow a UV set even where no texture reads it (KHR_materials_anisotropy).
    const FloatArray* uvs[2] = {
        optional("TEXCOORD_0", 2, needs.uv0 || needs.uv1 || needs.normalMapTexCoord == 0),
        optional("TEXCOORD_1", 2, needs.uv1 || needs.normalMapTexCoord == 1)};
    const bool normalMap = needs.normalMapTexCoord >= 0;
    const FloatArray* tangents = optional("TANGENT", 4, normalMap);
    // COLOR_0 is RGB or RGBA (float, or normalized unsigned byte or short).
    const int colorAccessor = attribute("COLOR_0");
    const bool rgb = colorAccessor >= 0 && size_t(colorAccessor) < model_.accessors.size() &&
                     model_.accessors[colorAccessor].type == TINYGLTF_TYPE_VEC3;
    const FloatArray* colors = optional("COLOR_0", rgb ? 3 : 4, true);
    needColors_ |= colors != nullptr;
    // Morph targets and skins pose copies of the attributes (accessors may be shared).
    FloatArray posed[3];
    if (deformation && deformation->active()) {
        posed[0] = *points;
        points = &posed[0];
        if (normals) {
            posed[1] = *normals;
            normals = &posed[1];
        }
        if (tangents) {
            posed[2] = *tangents;
            tangents = &posed[2];
        }
        deformPrimitive(reader_, file_, primitive, where, *deformation, posed[0],
                        normals ? &posed[1] : nullptr, tangents ? &posed[2] : nullptr);
    }
    if ((needs.uv0 && !uvs[0]) || (needs.uv1 && !uvs[1])) {
        ++missingUvs_;
    }
    needUv0_ |= needs.uv0;
    needUv1_ |= needs.uv1;
    needTangents_ |= normalMap;

    const std::vector<uint32_t> order = corners(mode, points->count, primitive.indices, where);
    // A mirroring transform turns counter-clockwise into clockwise; swapping two corners keeps
    // the front face where the file meant it. Normals transform by the inverse transpose.
    const glm::dmat3 linear(world);
    const bool mirrored = glm::determinant(linear) < 0.0;
    const glm::dmat3 normalMatrix = glm::inverseTranspose(linear);
    const std::vector<glm::vec4> generated =
        normalMap && !tangents ? mikkTangents(*points, normals, uvs[needs.normalMapTexCoord], order)
                               : std::vector<glm::vec4>{};
    for (size_t t = 0; t < order.size(); t += 3) {
        uint32_t idx[3] = {order[t], order[t + 1], order[t + 2]};
        size_t slot[3] = {t, t + 1, t + 2}; // corners of `generated`
        if (mirrored) {
            std::swap(idx[1], idx[2]);
            std::swap(slot[1], slot[2]);
        }
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            const float* q = (*points)[idx[k]];
            p[k] = glm::vec3(world * glm::dvec4(q[0], q[1], q[2], 1.0));
            if (!finite(p[k])) {
                fail(file_, where + ": a vertex is not finite after the node transforms");
            }
        }
        if (isDegenerate(p[0], p[1], p[2])) {
            ++degenerateTriangles_;
            continue;
        }
        triangles_.push_back(Triangle{p[0], material, p[1], WF_NO_EMITTER, p[2], 0u});
        if (grouping_)
            meshOf_.push_back(mesh);
        const glm::vec3 ng = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
        glm::vec3 n[3] = {ng, ng, ng};
        for (int k = 0; k < 3 && normals; ++k) {
            const float* q = (*normals)[idx[k]];
            const glm::vec3 shading(glm::normalize(normalMatrix * glm::dvec3(q[0], q[1], q[2])));
            n[k] = finite(shading) ? shading : ng; // a zero NORMAL falls back to flat
            smoothNormals_ |= glm::dot(n[k], ng) < 0.9999f;
        }
        if (!storeNormals_ && (smoothNormals_ || needTangents_)) {
            surface_.normals.reserve(triangles_.capacity());
            fillFlatNormals(triangles_.size() - 1);
            storeNormals_ = true;
        }
        if (storeNormals_)
            surface_.normals.push_back({octEncode(n[0]), octEncode(n[1]), octEncode(n[2]), 0u});
        TriangleUvs uv[2] = {};
        for (int set = 0; set < 2; ++set) {
            glm::vec2* corner[3] = {&uv[set].uv0, &uv[set].uv1, &uv[set].uv2};
            for (int k = 0; k < 3 && uvs[set]; ++k) {
                *corner[k] = glm::vec2((*uvs[set])[idx[k]][0], (*uvs[set])[idx[k]][1]);
            }
        }
        if (needUv0_) {
            surface_.uv0.resize(triangles_.size() - 1);
            surface_.uv0.push_back(uv[0]);
        }
        if (needUv1_) {
            surface_.uv1.resize(triangles_.size() - 1);
            surface_.uv1.push_back(uv[1]);
        }
        if (needColors_) {
            TriangleColors corners{kOpaqueWhite, kOpaqueWhite, kOpaqueWhite, 0u};
            uint32_t* packed[3] = {&corners.c0, &corners.c1, &corners.c2};
            for (int k = 0; k < 3 && colors; ++k) {
                const float* q = (*colors)[idx[k]];
                *packed[k] = glm::packUnorm4x8(glm::vec4(q[0], q[1], q[2], rgb ? 1.0f : q[3]));
            }
            surface_.colors.resize(triangles_.size() - 1, {kOpaqueWhite, kOpaqueWhite, kOpaqueWhite, 0u});
            surface_.colors.push_back(corners);
        }
        if (!needTangents_) {
            continue;
        }
        TriangleTangents frame{};
        if (normalMap) {
            uint32_t packed[3];
            for (int k = 0; k < 3; ++k) {
                const float* q = tangents ? (*tangents)[idx[k]] : &generated[slot[k]].x;
                glm::vec3 axis(glm::normalize(linear * glm::dvec3(q[0], q[1], q[2])));
                packed[k] = octEncode(finite(axis) ? axis : orthogonal(n[k]));
                frame.signs |= ((q[3] < 0.0f) != mirrored) ? 1u << k : 0u;
            }
            frame = {packed[0], packed[1], packed[2], frame.signs};
        }
        surface_.tangents.resize(triangles_.size() - 1);
        surface_.tangents.push_back(frame);
    }
}

void PrimitiveBuilder::fillFlatNormals(size_t upTo) {
    for (size_t i = surface_.normals.size(); i < upTo; ++i) {
        const Triangle& t = triangles_[i];
        const uint32_t flat = octEncode(glm::normalize(glm::cross(t.p1 - t.p0, t.p2 - t.p0)));
        surface_.normals.push_back({flat, flat, flat, 0u});
    }
}

void PrimitiveBuilder::place(uint32_t mesh, const glm::dmat4& world, const std::string& where,
                             std::vector<glm::mat4> motion) {
    // A zero scale flattens the mesh to nothing, and a huge one overflows float: flattened,
    // every triangle would be dropped as degenerate; and an inverse would not be finite.
    auto invertible = [](const glm::dmat4& m) {
        const double det = glm::determinant(glm::dmat3(m));
        return std::abs(det) >= double(std::numeric_limits<float>::min()) &&
               std::abs(det) <= double(std::numeric_limits<float>::max());
    };
    if (!invertible(world)) {
        ++flatteningPlacements_;
        return;
    }
    if (!std::all_of(motion.begin(), motion.end(),
                     [&](const glm::mat4& key) { return invertible(glm::dmat4(key)); }))
        motion.clear();
    if (placements_.size() >= kMaxInstances)
        fail(file_, where + ": more than " + std::to_string(kMaxInstances) + " instances");
    placements_.push_back({glm::mat4(world), mesh, std::move(motion)});
}

// A stable counting sort of the triangles (and every per-triangle array) by mesh, world
// geometry first; placements of meshes left empty (all their triangles degenerate) go.
void PrimitiveBuilder::groupByMesh(Scene& scene) {
    const size_t n = triangles_.size();
    meshOf_.resize(n, kWorldGeometry);
    std::vector<size_t> start(size_t(meshCount_) + 2, 0);
    for (uint32_t m : meshOf_)
        ++start[m == kWorldGeometry ? 1 : size_t(m) + 2];
    for (size_t g = 1; g < start.size(); ++g)
        start[g] += start[g - 1];
    std::vector<uint32_t> order(n);
    {
        std::vector<size_t> next(start.begin(), start.end() - 1);
        for (size_t i = 0; i < n; ++i)
            order[next[meshOf_[i] == kWorldGeometry ? 0 : size_t(meshOf_[i]) + 1]++] = uint32_t(i);
    }
    meshOf_ = {};
    permuteInPlace(triangles_, order);
    permuteInPlace(surface_.normals, order);
    permuteInPlace(surface_.tangents, order);
    permuteInPlace(surface_.uv0, order);
    permuteInPlace(surface_.uv1, order);
    permuteInPlace(surface_.colors, order);
    std::vector<uint32_t> kept(meshCount_, kWorldGeometry);
    std::vector<Bounds> boxes;
    for (uint32_t m = 0; m < meshCount_; ++m) {
        const MeshRange range{uint32_t(start[m + 1]), uint32_t(start[m + 2] - start[m + 1])};
        if (range.triangleCount == 0)
            continue;
        kept[m] = uint32_t(scene.meshes.size());
        scene.meshes.push_back(range);
        Bounds& box = boxes.emplace_back();
        for (uint32_t i = range.firstTriangle; i < range.firstTriangle + range.triangleCount; ++i)
            for (const glm::vec3& p : {triangles_[i].p0, triangles_[i].p1, triangles_[i].p2})
                box.grow(p);
    }
    for (const MeshPlacement& placement : placements_) {
        const uint32_t mesh = kept[placement.mesh];
        if (mesh == kWorldGeometry)
            continue;
        bool finiteBoxes = true;
        for (const glm::mat4& key : placement.motion) {
            const Bounds moved = transformedBounds(boxes[mesh], key);
            finiteBoxes = finiteBoxes && finite(moved.lo) && finite(moved.hi);
        }
        const Bounds box = transformedBounds(boxes[mesh], placement.worldFromObject);
        if (!finite(box.lo) || !finite(box.hi) || !finiteBoxes)
            fail(file_, "an instanced mesh is not finite after its node's transforms");
        scene.placements.push_back({placement.worldFromObject, mesh, placement.motion});
    }
    placements_ = {};
}

void PrimitiveBuilder::finish(Scene& scene) {
    if (flatteningPlacements_ > 0) {
        warn(file_, "skipped " + std::to_string(flatteningPlacements_) +
                        " placements of instanced meshes whose transform has a zero or "
                        "overflowing scale (flattened, every triangle would be degenerate)");
    }
    if (skippedPrimitives_ > 0) {
        warn(file_, "skipped " + std::to_string(skippedPrimitives_) +
                        " point or line primitives (only triangles are rendered)");
    }
    if (missingUvs_ > 0) {
        warn(file_, std::to_string(missingUvs_) + " textured primitives lack the TEXCOORD "
                    "attribute their textures use; they sample one texel");
    }
    if (degenerateTriangles_ > 0) {
        warn(file_, "dropped " + std::to_string(degenerateTriangles_) + " degenerate triangles",
             "note");
    }
    const size_t n = triangles_.size();
    // Arrays that some triangle needed are padded to one entry per triangle; the others go.
    auto keep = [n](auto& array, bool needed) {
        if (needed) {
            array.resize(n);
        } else {
            array.clear();
            array.shrink_to_fit();
        }
    };
    if (smoothNormals_ || needTangents_)
        fillFlatNormals(n);
    keep(surface_.tangents, needTangents_);
    keep(surface_.normals, smoothNormals_ || needTangents_);
    keep(surface_.uv0, needUv0_);
    keep(surface_.uv1, needUv1_);
    if (needColors_)
        surface_.colors.resize(n, {kOpaqueWhite, kOpaqueWhite, kOpaqueWhite, 0u});
    if (meshCount_ > 0)
        groupByMesh(scene);
    scene.triangles = std::move(triangles_);
    scene.surface.normals = std::move(surface_.normals);
    scene.surface.tangents = std::move(surface_.tangents);
    scene.surface.uv0 = std::move(surface_.uv0);
    scene.surface.uv1 = std::move(surface_.uv1);
    scene.surface.colors = std::move(surface_.colors);
}

} // namespace wf::gltf
