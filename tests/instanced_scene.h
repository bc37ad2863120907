// A glTF scene for the instancing tests: a lopsided, smooth-shaded blob (its own mirror image
// differs from it) placed by three nodes (rotated, mirrored, non-uniformly scaled), a floor and
// an emissive quad placed once each, and a camera.
#pragma once
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/png_writer.h"
#include "mini_gltf.h"

namespace wf::test {

struct BlobMesh {
    std::vector<float> positions; // xyz
    std::vector<float> normals;   // xyz, area-weighted face normals
    std::vector<float> uvs;       // the sphere's longitude and latitude, seam duplicated
    std::vector<uint16_t> indices;
};

inline BlobMesh blobMesh(int rings = 8) {
    BlobMesh mesh;
    const int segments = 2 * rings;
    std::vector<glm::vec3> points;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s <= segments; ++s) {
            const float theta = float(M_PI) * float(r) / float(rings);
            const float phi = 2.0f * float(M_PI) * float(s) / float(segments);
            glm::vec3 p(std::sin(theta) * std::cos(phi), std::cos(theta),
                        std::sin(theta) * std::sin(phi));
            p.x += 0.6f * std::max(p.x, 0.0f) * std::max(p.x, 0.0f); // a bulge on +x only
            p.y *= 0.8f + 0.2f * (p.z + 1.0f);                        // taller towards +z
            points.push_back(p);
            mesh.uvs.insert(mesh.uvs.end(), {float(s) / float(segments), float(r) / float(rings)});
        }
    std::vector<glm::vec3> normals(points.size(), glm::vec3(0.0f));
    auto at = [&](int r, int s) { return uint16_t(r * (segments + 1) + s); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const uint16_t quad[4] = {at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1)};
            for (const auto& tri : {std::array<int, 3>{0, 2, 1}, std::array<int, 3>{0, 3, 2}}) {
                const uint16_t a = quad[tri[0]], b = quad[tri[1]], c = quad[tri[2]];
                const glm::vec3 n = glm::cross(points[b] - points[a], points[c] - points[a]);
                if (glm::length(n) < 1e-7f)
                    continue; // the poles' collapsed quads
                mesh.indices.insert(mesh.indices.end(), {a, b, c});
                for (uint16_t v : {a, b, c})
                    normals[v] += n;
            }
        }
    for (size_t i = 0; i < points.size(); ++i) {
        const glm::vec3 n = glm::length(normals[i]) > 0.0f ? glm::normalize(normals[i])
                                                            : glm::vec3(0.0f, 1.0f, 0.0f);
        mesh.positions.insert(mesh.positions.end(), {points[i].x, points[i].y, points[i].z});
        mesh.normals.insert(mesh.normals.end(), {n.x, n.y, n.z});
    }
    return mesh;
}

// Writes the scene; `blobMaterial` is the blob's glTF material JSON. With `normalMapPng` (the
// bytes of a PNG), the blob gets UVs and that image as texture 0, for a material that names it.
inline std::string writeInstancedScene(const TempDir& dir, const std::string& blobMaterial =
                                           R"({"pbrMetallicRoughness":{"baseColorFactor":
                                           [0.8,0.5,0.3,1],"metallicFactor":0,
                                           "roughnessFactor":0.35}})",
                                       const std::string& normalMapPath = "") {
    MiniGltf g;
    const BlobMesh blob = blobMesh();
    std::string uvAttribute;
    if (!normalMapPath.empty()) {
        const int uvs = g.addAccessor(g.addView(blob.uvs.data(), blob.uvs.size() * sizeof(float)),
                                      F32, blob.uvs.size() / 2, "VEC2");
        uvAttribute = ",\"TEXCOORD_0\":" + std::to_string(uvs);
        g.images.push_back("{\"uri\":\"" + normalMapPath + "\"}");
        g.textures.push_back(R"({"source":0})");
    }
    const int positions = g.addPositions(blob.positions);
    const int normals = g.addAccessor(
        g.addView(blob.normals.data(), blob.normals.size() * sizeof(float)), F32,
        blob.normals.size() / 3, "VEC3");
    const int indices = g.addIndices(blob.indices, U16);
    g.materials.push_back(blobMaterial);
    g.materials.push_back(R"({"pbrMetallicRoughness":{"baseColorFactor":[0.7,0.7,0.7,1],
                          "metallicFactor":0,"roughnessFactor":1}})");
    g.materials.push_back(R"({"emissiveFactor":[1,1,1],"extensions":{
                          "KHR_materials_emissive_strength":{"emissiveStrength":12}}})");
    g.addMesh(positions, indices, 0, 4, ",\"NORMAL\":" + std::to_string(normals) + uvAttribute);
    const std::vector<float> floor = {-4, 0, -4, -4, 0, 4, 4, 0, 4, -4, 0, -4, 4, 0, 4, 4, 0, -4};
    g.addMesh(g.addPositions(floor), -1, 1);
    const std::vector<float> lamp = {-1, 4, -1, 1, 4, -1, 1, 4, 1, -1, 4, -1, 1, 4, 1, -1, 4, 1};
    g.addMesh(g.addPositions(lamp), -1, 2);
    g.cameras.push_back(R"({"type":"perspective","perspective":{"yfov":0.9,"znear":0.1}})");
    g.nodes = {
        R"({"mesh":0,"translation":[-2,1,0],"rotation":[0,0.3826834,0,0.9238795]})",
        R"({"mesh":0,"translation":[0,1.2,-0.5],"scale":[-1,1,1],"rotation":[0.2588190,0,0,0.9659258]})",
        R"({"mesh":0,"translation":[2.1,0.8,0.3],"scale":[1.5,0.6,0.9]})",
        R"({"mesh":1})",
        R"({"mesh":2})",
        R"({"camera":0,"translation":[0,2.5,7],"rotation":[-0.1305262,0,0,0.9914449]})",
    };
    g.scenes = R"([{"nodes":[0,1,2,3,4,5]}])";
    return g.write(dir);
}

// The same scene with a normal map that tilts every normal along the tangent frame's
// bitangent (the blob gets MikkTSpace tangents): a frame whose handedness a mirroring
// placement fails to flip tilts the other way.
inline std::string writeNormalMappedInstancedScene(const TempDir& dir) {
    // writePngPreview stores sRGB codes of linear values: store the codes of n = (0, 0.6, 0.8).
    auto code = [](float unit) {
        const float c = std::round((unit * 0.5f + 0.5f) * 255.0f) / 255.0f;
        return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
    };
    std::vector<float> texels;
    for (int i = 0; i < 4; ++i)
        texels.insert(texels.end(), {code(0.0f), code(0.6f), code(0.8f)});
    writePngPreview(dir.file("tilt.png"), 2, 2, texels);
    return writeInstancedScene(dir, R"({"pbrMetallicRoughness":{"baseColorFactor":
        [0.8,0.8,0.8,1],"metallicFactor":0,"roughnessFactor":0.3},
        "normalTexture":{"index":0}})", "tilt.png");
}

} // namespace wf::test
