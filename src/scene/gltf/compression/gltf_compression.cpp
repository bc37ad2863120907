// Step 2 of gltf_compression.h: decoding, in an order that lets a Draco bitstream sit in a
// meshopt-compressed bufferView (meshopt views first).
#include "scene/gltf/compression/gltf_compression.h"

#include <tiny_gltf.h>

#include <set>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/compression/gltf_codecs.h"
#include "scene/gltf/io/gltf_file_access.h"

namespace wf::gltf {

int appendBufferView(tinygltf::Model& model, std::vector<unsigned char> bytes) {
    tinygltf::BufferView view;
    view.buffer = int(model.buffers.size());
    view.byteLength = bytes.size();
    model.buffers.emplace_back();
    model.buffers.back().data = std::move(bytes);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size() - 1);
}

namespace {

// Declared sizes, summed before anything is decoded: decoded data shares the scene files'
// 2 GiB budget, so a small file cannot ask for gigabytes.
void checkDecodedBudget(const tinygltf::Model& model, const CompressionPlan& plan,
                        const std::string& file) {
    std::uintmax_t total = 0;
    for (const MeshoptView& m : plan.meshopt) {
        total += std::uintmax_t(m.count) * m.byteStride; // both below 2^40 (the plan)
    }
    std::set<int> counted; // primitives may share one stream and its accessors
    for (const DracoPrimitive& d : plan.draco) {
        std::vector<int> accessors{d.indices};
        const auto& mesh = model.meshes[d.mesh].primitives[d.primitive];
        for (const auto& [name, id] : d.attributes) {
            const auto found = mesh.attributes.find(name);
            accessors.push_back(found == mesh.attributes.end() ? -1 : found->second);
        }
        for (int a : accessors) {
            if (a < 0 || std::size_t(a) >= model.accessors.size() || !counted.insert(a).second) {
                continue; // decodeDraco names a bad index
            }
            const tinygltf::Accessor& acc = model.accessors[a];
            if (acc.count > MAX_ACCESSOR_ELEMENTS) {
                fail(file, "accessor " + std::to_string(a) + " has " +
                               std::to_string(acc.count) + " elements, over the limit of " +
                               std::to_string(MAX_ACCESSOR_ELEMENTS));
            }
            total += std::uintmax_t(acc.count) * 16; // a VEC4 of floats at most
        }
    }
    if (total > MAX_TOTAL_BYTES) {
        fail(file, "its compressed data would decode to " + std::to_string(total >> 20) +
                       " MiB, over the limit of " + std::to_string(MAX_TOTAL_BYTES >> 20) +
                       " MiB");
    }
}

// Every compressed object tinygltf parsed must be in the plan (a key written with JSON
// escapes would pass the plan's text test unseen).
void checkPlanComplete(const tinygltf::Model& model, const CompressionPlan& plan,
                       const std::string& file) {
    std::size_t views = 0, primitives = 0;
    for (const tinygltf::BufferView& view : model.bufferViews) {
        const auto& e = view.extensions;
        views += e.count(MESHOPT_NAMES[0]) + e.count(MESHOPT_NAMES[1]) > 0;
    }
    for (const tinygltf::Mesh& mesh : model.meshes) {
        for (const tinygltf::Primitive& p : mesh.primitives) {
            primitives += p.extensions.count(DRACO);
        }
    }
    if (views != plan.meshopt.size() || primitives != plan.draco.size()) {
        fail(file, "its compression extensions could not be read consistently");
    }
}

void decodeMeshoptViews(tinygltf::Model& model, const CompressionPlan& plan,
                        const std::string& file) {
    for (const MeshoptView& m : plan.meshopt) {
        const std::string where = "bufferView " + std::to_string(m.view);
        checkIndex(file, m.view, model.bufferViews.size(), "bufferView", m.extension);
        checkIndex(file, m.buffer, model.buffers.size(), "buffer", where + " " + m.extension);
        if (plan.placeholders.count(m.buffer)) {
            fail(file, where + " " + m.extension + " reads buffer " + std::to_string(m.buffer) +
                           ", a fallback buffer without data");
        }
        const std::vector<unsigned char>& source = model.buffers[m.buffer].data;
        if (m.byteLength > source.size() || m.byteOffset > source.size() - m.byteLength) {
            fail(file, where + " " + m.extension + ": " + std::to_string(m.byteLength) +
                           " bytes at offset " + std::to_string(m.byteOffset) +
                           " extend past the end of buffer " + std::to_string(m.buffer) + " (" +
                           std::to_string(source.size()) + " bytes)");
        }
        tinygltf::BufferView& view = model.bufferViews[m.view];
        if (view.byteLength != m.count * m.byteStride) {
            fail(file, where + ": byteLength " + std::to_string(view.byteLength) +
                           " is not the " + m.extension + " byteStride x count (" +
                           std::to_string(m.byteStride) + " x " + std::to_string(m.count) + ")");
        }
        if (view.byteStride != 0 && view.byteStride != m.byteStride) {
            fail(file, where + ": byteStride " + std::to_string(view.byteStride) +
                           " differs from the " + m.extension + " byteStride " +
                           std::to_string(m.byteStride));
        }
        const auto fallback = plan.placeholders.find(view.buffer);
        if (fallback != plan.placeholders.end() &&
            (view.byteOffset > fallback->second ||
             view.byteLength > fallback->second - view.byteOffset)) {
            fail(file, where + " extends past the end of its fallback buffer " +
                           std::to_string(view.buffer) + " (" + std::to_string(fallback->second) +
                           " bytes)");
        }
        std::vector<unsigned char> decoded =
            decodeMeshopt(m, source.data() + m.byteOffset, file);
        view.buffer = int(model.buffers.size()); // `source` is not used past this point
        view.byteOffset = 0;
        model.buffers.emplace_back();
        model.buffers.back().data = std::move(decoded);
    }
    // Only compressed views may refer to a fallback buffer: the rest would read 4 bytes.
    std::set<int> decodedViews;
    for (const MeshoptView& m : plan.meshopt) {
        decodedViews.insert(m.view);
    }
    for (std::size_t v = 0; v < model.bufferViews.size(); ++v) {
        if (!decodedViews.count(int(v)) && plan.placeholders.count(model.bufferViews[v].buffer)) {
            fail(file, "bufferView " + std::to_string(v) + " refers to buffer " +
                           std::to_string(model.bufferViews[v].buffer) +
                           ", a meshopt fallback buffer without data, but is not compressed");
        }
    }
}

void decodeDracoPrimitives(tinygltf::Model& model, const CompressionPlan& plan,
                           const std::string& file) {
    // Encoders may let primitives share one Draco stream and its accessors; each accessor is
    // decoded once, and may not be claimed by two different streams.
    std::map<int, std::pair<int, int>> owner; // accessor -> (bufferView, Draco id or -1)
    for (const DracoPrimitive& d : plan.draco) {
        tinygltf::Primitive& primitive = model.meshes[d.mesh].primitives[d.primitive];
        std::vector<std::pair<int, int>> claims{{d.indices, -1}};
        for (const auto& [name, id] : d.attributes) {
            const auto found = primitive.attributes.find(name);
            if (found != primitive.attributes.end()) {
                claims.emplace_back(found->second, id);
            }
        }
        bool decoded = true;
        for (const auto& [accessor, id] : claims) {
            const auto previous = owner.find(accessor);
            if (previous == owner.end()) {
                decoded = false;
            } else if (previous->second != std::make_pair(d.bufferView, id)) {
                fail(file, "accessor " + std::to_string(accessor) +
                               " is the target of two different Draco streams");
            }
        }
        if (!decoded) {
            decodeDraco(model, d, file);
            for (const auto& claim : claims) {
                owner[claim.first] = {d.bufferView, claim.second};
            }
        }
        primitive.indices = d.indices;
    }
}

} // namespace

void decompress(tinygltf::Model& model, const CompressionPlan& plan, const std::string& file) {
    checkPlanComplete(model, plan, file);
    for (const DracoPrimitive& d : plan.draco) { // the plan read the same arrays
        checkIndex(file, d.mesh, model.meshes.size(), "mesh", DRACO);
        checkIndex(file, d.primitive, model.meshes[d.mesh].primitives.size(), "primitive",
                   "mesh " + std::to_string(d.mesh));
    }
    checkDecodedBudget(model, plan, file);
    decodeMeshoptViews(model, plan, file);
    decodeDracoPrimitives(model, plan, file);
}

} // namespace wf::gltf
