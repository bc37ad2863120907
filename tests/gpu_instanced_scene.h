// A glTF scene for the EXT_mesh_gpu_instancing tests, in two forms that must load alike: one
// node whose extension places the lopsided blob (instanced_scene.h) at N instance transforms,
// and the same node without the extension but with one child node per instance carrying the
// instance's translation, rotation and scale. Both sit under a transformed root, and the node
// has a transform of its own, so the order world = root x node x instance shows.
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "instanced_scene.h"
#include "mini_gltf.h"

namespace wf::test {

constexpr int I8 = 5120, I16 = 5122;

struct GpuInstancingCase {
    std::size_t count = 0;
    std::vector<float> translation, scale; // xyz per instance; empty: the attribute is absent
    std::vector<float> rotation;           // xyzw per instance, as the loader should decode it
    // Where not empty, ROTATION is stored as these normalized integers of rotationType (I8 or
    // I16) instead of `rotation` (which then holds what the spec says they decode to).
    std::vector<int> rotationInts;
    int rotationType = F32;
    std::string material;    // the mesh's material as JSON; empty: none
    bool animated = false;   // the node's translation animated over one second
    bool camera = false;     // a camera looking at the instances
};

struct GpuInstancingFile {
    MiniGltf g;
    int translation = -1, rotation = -1, scale = -1; // the instance accessors (gpu form)
};

inline std::string number(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", double(v)); // exact: as a double, the float
    return text;
}

inline std::string numbers(const std::vector<float>& v, std::size_t first, std::size_t n) {
    std::string out = "[";
    for (std::size_t k = 0; k < n; ++k)
        out += (k ? "," : "") + number(v[first + k]);
    return out + "]";
}

// `gpu`: the extension's form; else the child nodes' form.
inline GpuInstancingFile gpuInstancingScene(const GpuInstancingCase& c, bool gpu) {
    GpuInstancingFile f;
    MiniGltf& g = f.g;
    const BlobMesh blob = blobMesh(4);
    const int positions = g.addPositions(blob.positions);
    const int normals = g.addAccessor(
        g.addView(blob.normals.data(), blob.normals.size() * sizeof(float)), F32,
        blob.normals.size() / 3, "VEC3");
    const int indices = g.addIndices(blob.indices, U16);
    if (!c.material.empty())
        g.materials = {c.material};
    g.addMesh(positions, indices, c.material.empty() ? -1 : 0, 4,
              ",\"NORMAL\":" + std::to_string(normals));
    const std::string root = R"({"translation":[0.5,-1,2],"rotation":[0,0.6,0,0.8],"children":[1]})";
    const std::string nodeTransform =
        R"("translation":[1,0.25,-0.5],"rotation":[0.1,0.2,0.3,0.927361849549570],"scale":[1.5,1,0.75])";
    g.nodes = {root};
    if (gpu) {
        std::string attributes;
        auto add = [&](const char* name, int accessor) {
            attributes += std::string(attributes.empty() ? "" : ",") + "\"" + name +
                          "\":" + std::to_string(accessor);
        };
        if (!c.translation.empty()) {
            f.translation = g.addAccessor(g.addView(c.translation.data(), c.translation.size() * 4),
                                          F32, c.count, "VEC3");
            add("TRANSLATION", f.translation);
        }
        if (!c.rotationInts.empty()) {
            std::vector<uint8_t> bytes;
            for (int v : c.rotationInts) {
                bytes.push_back(uint8_t(v & 0xff));
                if (c.rotationType == I16)
                    bytes.push_back(uint8_t((v >> 8) & 0xff));
            }
            const int view = g.addView(bytes.data(), bytes.size());
            g.accessors.push_back("{\"bufferView\":" + std::to_string(view) +
                                  ",\"componentType\":" + std::to_string(c.rotationType) +
                                  ",\"normalized\":true,\"count\":" + std::to_string(c.count) +
                                  ",\"type\":\"VEC4\"}");
            f.rotation = int(g.accessors.size()) - 1;
            add("ROTATION", f.rotation);
        } else if (!c.rotation.empty()) {
            f.rotation = g.addAccessor(g.addView(c.rotation.data(), c.rotation.size() * 4), F32,
                                       c.count, "VEC4");
            add("ROTATION", f.rotation);
        }
        if (!c.scale.empty()) {
            f.scale = g.addAccessor(g.addView(c.scale.data(), c.scale.size() * 4), F32, c.count,
                                    "VEC3");
            add("SCALE", f.scale);
        }
        g.nodes.push_back("{\"mesh\":0," + nodeTransform +
                          ",\"extensions\":{\"EXT_mesh_gpu_instancing\":{\"attributes\":{" +
                          attributes + "}}}}");
        g.extra = R"(,"extensionsUsed":["EXT_mesh_gpu_instancing"])";
    } else {
        std::string children;
        for (std::size_t i = 0; i < c.count; ++i)
            children += (i ? "," : "") + std::to_string(2 + i);
        g.nodes.push_back("{" + nodeTransform + ",\"children\":[" + children + "]}");
        for (std::size_t i = 0; i < c.count; ++i) {
            std::string node = "{\"mesh\":0";
            if (!c.translation.empty())
                node += ",\"translation\":" + numbers(c.translation, 3 * i, 3);
            if (!c.rotation.empty())
                node += ",\"rotation\":" + numbers(c.rotation, 4 * i, 4);
            if (!c.scale.empty())
                node += ",\"scale\":" + numbers(c.scale, 3 * i, 3);
            g.nodes.push_back(node + "}");
        }
    }
    if (c.camera) { // a root of its own, after the others
        g.cameras = {R"({"type":"perspective","perspective":{"yfov":0.9,"znear":0.05}})"};
        g.nodes.push_back(R"({"translation":[0,1,14],"camera":0})");
        g.scenes = "[{\"nodes\":[0," + std::to_string(g.nodes.size() - 1) + "]}]";
    }
    if (c.animated) {
        const std::vector<float> times = {0.0f, 1.0f}, moves = {0, 0, 0, 2, 1, -1};
        const int input = g.addAccessor(g.addView(times.data(), 8), F32, 2, "SCALAR");
        g.accessors.back().insert(g.accessors.back().size() - 1, ",\"min\":[0],\"max\":[1]");
        const int output = g.addAccessor(g.addView(moves.data(), 24), F32, 2, "VEC3");
        g.extra += R"(,"animations":[{"samplers":[{"input":)" + std::to_string(input) +
                   R"(,"output":)" + std::to_string(output) +
                   R"(}],"channels":[{"sampler":0,"target":{"node":1,"path":"translation"}}]}])";
    }
    return f;
}

// Instance transforms for `n` instances: spread out, every rotation different, one scale
// mirroring and the others non-uniform.
inline GpuInstancingCase gpuInstancingCase(std::size_t n) {
    GpuInstancingCase c;
    c.count = n;
    for (std::size_t i = 0; i < n; ++i) {
        const float a = 0.7f * float(i) + 0.3f;
        c.translation.insert(c.translation.end(),
                             {2.5f * float(i) - 4.0f, 0.5f * float(i % 2), -0.25f * float(i)});
        const float x = std::sin(a), y = std::cos(1.3f * a), z = 0.5f * std::sin(2.1f * a),
                    w = 0.8f + 0.1f * float(i);
        const float len = std::sqrt(x * x + y * y + z * z + w * w);
        c.rotation.insert(c.rotation.end(), {x / len, y / len, z / len, w / len});
        c.scale.insert(c.scale.end(), {i == 1 ? -1.0f : 1.0f + 0.1f * float(i), 0.8f,
                                       1.25f - 0.05f * float(i)});
    }
    return c;
}

} // namespace wf::test
