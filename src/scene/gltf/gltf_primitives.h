// One glTF primitive to world-space triangles plus, per triangle, what shading may need:
// shading normals (NORMAL, else flat), UVs (TEXCOORD_0/1) and tangents (TANGENT, else MikkTSpace
// frames from the normal map's UVs, tangent_generation.h). Triangle lists, strips and fans;
// indexed or not. The loader decides at the end which of the collected attributes it keeps.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/posing/gltf_deformation.h"
#include "scene/gltf/gltf_materials.h"
#include "scene/scene.h"

namespace tinygltf {
class Model;
struct Primitive;
} // namespace tinygltf

namespace wf::gltf {

// The `mesh` of add() for geometry flattened into world space.
constexpr uint32_t kWorldGeometry = 0xffffffffu;

// Octahedral encoding of a unit vector in two 16-bit snorms (decoded by octDecode).
uint32_t octEncode(glm::vec3 n);

class PrimitiveBuilder {
public:
    // `materials` and `defaultMaterial` (the index primitives without material get) must
    // outlive the builder; so must model and file.
    PrimitiveBuilder(const tinygltf::Model& model, const std::string& file,
                     const MaterialTables& materials, uint32_t defaultMaterial);

    // Flattened geometry comes with its world transform and kWorldGeometry; an instanced mesh's
    // with the identity and the slot newMesh() gave it, and place() adds its placements.
    // `deformation` (morph weights, a skin's joint matrices) poses the vertices first; a skinned
    // primitive comes with the identity as `world` (its joints place it).
    void add(const tinygltf::Primitive& primitive, const std::string& where,
             const glm::dmat4& world, uint32_t mesh = kWorldGeometry,
             const Deformation* deformation = nullptr);
    uint32_t newMesh() { return meshCount_++; }
    // Room for the triangles the accessors' counts promise, so the arrays never grow by copying.
    void reserve(size_t triangles) { triangles_.reserve(triangles); }
    // `motion`: worldFromObject keys over the shutter, for a placement that moves (kept only
    // where every key is invertible; else the placement stays at `world`).
    void place(uint32_t mesh, const glm::dmat4& world, const std::string& where,
               std::vector<glm::mat4> motion = {});
    // Moves the triangles into `scene` (world geometry first, then mesh by mesh) with the
    // placements of the meshes left with triangles, and keeps only the attributes it needs.
    void finish(Scene& scene);
    bool usedDefaultMaterial() const { return usedDefault_; }

private:
    std::vector<uint32_t> corners(int mode, size_t vertexCount, int indices,
                                  const std::string& where);

    const tinygltf::Model& model_;
    const std::string& file_;
    const MaterialTables& materials_;
    uint32_t defaultMaterial_;
    AccessorReader reader_;
    void groupByMesh(Scene& scene);
    // Per-triangle normals are kept only once some triangle needs them; the triangles before
    // it get their flat normals then.
    void fillFlatNormals(size_t upTo);

    std::vector<Triangle> triangles_;
    SurfaceData surface_; // every attribute array filled for every triangle
    std::vector<uint32_t> meshOf_; // per triangle, once some mesh is instanced: its slot
    bool grouping_ = false;
    uint32_t meshCount_ = 0;
    std::vector<MeshPlacement> placements_;
    size_t flatteningPlacements_ = 0; // dropped: a zero scale
    bool usedDefault_ = false;
    bool smoothNormals_ = false; // some NORMAL differs from the flat normal
    bool storeNormals_ = false;  // surface_.normals holds one entry per triangle so far
    bool needUv0_ = false, needUv1_ = false, needTangents_ = false, needColors_ = false;
    static constexpr uint32_t kOpaqueWhite = 0xffffffffu; // COLOR_0 where a primitive has none
    size_t skippedPrimitives_ = 0;
    size_t degenerateTriangles_ = 0;
    size_t missingUvs_ = 0;
};

} // namespace wf::gltf
