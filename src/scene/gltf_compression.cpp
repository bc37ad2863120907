// The plan (JSON before tinygltf) and the decoding order (meshopt bufferViews first, since a
// Draco bitstream may itself sit in one). nlohmann/json is the parser tinygltf itself uses, so
// the plan sees the document as tinygltf will.
#include "scene/gltf_compression.h"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <cstring>
#include <set>
#include <string_view>

#include "scene/gltf_accessors.h"
#include "scene/gltf_codecs.h"
#include "scene/gltf_file_access.h"
#include "scene/gltf_materials.h"

namespace wf::gltf {
namespace {

using Json = nlohmann::json;

const char* const DRACO = "KHR_draco_mesh_compression";
const char* const MESHOPT_NAMES[] = {"EXT_meshopt_compression", "KHR_meshopt_compression"};
// tinygltf checks a data: URI's length against byteLength, so the stand-in is 4 real bytes.
const char* const PLACEHOLDER_URI = "data:application/octet-stream;base64,AAAAAA==";

// Counts, offsets and indices are JSON integers >= 0; anything else is refused by name.
std::size_t unsignedMember(const Json& object, const char* key, const std::string& where,
                           const std::string& file, bool required, std::size_t fallback = 0) {
    const auto found = object.find(key);
    if (found == object.end()) {
        if (required) {
            fail(file, where + " has no " + key);
        }
        return fallback;
    }
    if (!found->is_number_unsigned()) {
        fail(file, where + ": " + key + " must be an integer >= 0");
    }
    const std::uint64_t value = found->get<std::uint64_t>();
    if (value > std::uint64_t(1) << 40) { // far past any buffer's 1 GiB
        fail(file, where + ": " + key + " " + std::to_string(value) + " is absurdly large");
    }
    return std::size_t(value);
}

int indexMember(const Json& object, const char* key, const std::string& where,
                const std::string& file) {
    const std::size_t value = unsignedMember(object, key, where, file, true);
    if (value > std::size_t(INT32_MAX)) {
        fail(file, where + ": " + key + " is out of range");
    }
    return int(value);
}

const Json* extensionOf(const Json& object, const char* name) {
    if (!object.is_object()) {
        return nullptr;
    }
    const auto extensions = object.find("extensions");
    if (extensions == object.end() || !extensions->is_object()) {
        return nullptr;
    }
    const auto found = extensions->find(name);
    return found == extensions->end() ? nullptr : &*found;
}

// Refused here, before tinygltf, so that a file tinygltf cannot parse (a codec's accessors
// without bufferViews, say) is still refused by the extension it needs.
void checkRequired(const Json& doc, const std::string& file) {
    const auto required = doc.find("extensionsRequired");
    if (required == doc.end() || !required->is_array()) {
        return;
    }
    for (const Json& name : *required) {
        if (name.is_string() && !isSupportedExtension(name.get<std::string>())) {
            fail(file, "requires glTF extension " + name.get<std::string>() +
                           ", which is not supported");
        }
    }
}

MeshoptView readMeshopt(const Json& ext, int view, const char* name, const std::string& file) {
    const std::string where = "bufferView " + std::to_string(view) + " " + name;
    if (!ext.is_object()) {
        fail(file, where + " is not a JSON object");
    }
    MeshoptView m;
    m.view = view;
    m.extension = name;
    m.buffer = indexMember(ext, "buffer", where, file);
    m.byteOffset = unsignedMember(ext, "byteOffset", where, file, false);
    m.byteLength = unsignedMember(ext, "byteLength", where, file, true);
    m.byteStride = unsignedMember(ext, "byteStride", where, file, true);
    m.count = unsignedMember(ext, "count", where, file, true);
    const auto text = [&](const char* key, const char* fallback) {
        const auto found = ext.find(key);
        if (found == ext.end()) {
            return std::string(fallback);
        }
        if (!found->is_string()) {
            fail(file, where + ": " + key + " must be a string");
        }
        return found->get<std::string>();
    };
    const std::string mode = text("mode", "");
    if (mode == "ATTRIBUTES") {
        m.mode = MeshoptView::ATTRIBUTES;
    } else if (mode == "TRIANGLES") {
        m.mode = MeshoptView::TRIANGLES;
    } else if (mode == "INDICES") {
        m.mode = MeshoptView::INDICES;
    } else {
        fail(file, where + ": mode '" + mode + "' is not ATTRIBUTES, TRIANGLES or INDICES");
    }
    const std::string filter = text("filter", "NONE");
    if (filter == "NONE") {
        m.filter = MeshoptView::NONE;
    } else if (filter == "OCTAHEDRAL") {
        m.filter = MeshoptView::OCTAHEDRAL;
    } else if (filter == "QUATERNION") {
        m.filter = MeshoptView::QUATERNION;
    } else if (filter == "EXPONENTIAL") {
        m.filter = MeshoptView::EXPONENTIAL;
    } else {
        fail(file, where + ": filter '" + filter + "' is not supported (meshoptimizer 0.18 "
                           "decodes NONE, OCTAHEDRAL, QUATERNION and EXPONENTIAL)");
    }
    checkMeshoptParameters(m, file);
    return m;
}

DracoPrimitive readDraco(Json& primitive, const Json& ext, int mesh, int index,
                         const std::string& file) {
    const std::string where =
        "mesh " + std::to_string(mesh) + " primitive " + std::to_string(index) + " " + DRACO;
    if (!ext.is_object()) {
        fail(file, where + " is not a JSON object");
    }
    DracoPrimitive d;
    d.mesh = mesh;
    d.primitive = index;
    d.bufferView = indexMember(ext, "bufferView", where, file);
    const auto attributes = ext.find("attributes");
    if (attributes == ext.end() || !attributes->is_object()) {
        fail(file, where + " has no attributes object");
    }
    for (const auto& [name, id] : attributes->items()) {
        if (!id.is_number_unsigned() || id.get<std::uint64_t>() > std::uint64_t(INT32_MAX)) {
            fail(file, where + ": attribute " + name + " needs a Draco id (an integer >= 0)");
        }
        d.attributes.emplace_back(name, int(id.get<std::uint64_t>()));
    }
    // tinygltf refuses an indices accessor without bufferView, which Draco's are; the index
    // goes back on the primitive once its data is decoded.
    const auto indices = primitive.find("indices");
    if (indices != primitive.end()) {
        if (!indices->is_number_unsigned() ||
            indices->get<std::uint64_t>() > std::uint64_t(INT32_MAX)) {
            fail(file, where + ": the primitive's indices must be an accessor index");
        }
        d.indices = int(indices->get<std::uint64_t>());
        primitive.erase("indices");
    }
    return d;
}

// Collects the plan from the document and makes the two edits tinygltf needs. Returns whether
// the document changed.
bool plan(Json& doc, bool binary, CompressionPlan& out, const std::string& file) {
    bool changed = false;
    const auto array = [&](const char* key) -> Json* {
        const auto found = doc.find(key);
        return found != doc.end() && found->is_array() ? &*found : nullptr;
    };
    std::set<int> parents; // buffers that compressed bufferViews decode into
    if (Json* views = array("bufferViews")) {
        for (std::size_t i = 0; i < views->size() && i <= std::size_t(INT32_MAX); ++i) {
            for (const char* name : MESHOPT_NAMES) {
                if (const Json* ext = extensionOf((*views)[i], name)) {
                    out.meshopt.push_back(readMeshopt(*ext, int(i), name, file));
                    const auto buffer = (*views)[i].find("buffer");
                    if (buffer != (*views)[i].end() && buffer->is_number_unsigned() &&
                        buffer->get<std::uint64_t>() <= std::uint64_t(INT32_MAX)) {
                        parents.insert(int(buffer->get<std::uint64_t>()));
                    }
                    break; // a view with both names decodes once, by the EXT one
                }
            }
        }
    }
    if (Json* buffers = array("buffers")) {
        for (int b : parents) {
            if (b < 0 || std::size_t(b) >= buffers->size() || !(*buffers)[b].is_object()) {
                continue; // the loader names the bad index later
            }
            Json& buffer = (*buffers)[b];
            const bool glbChunk = binary && b == 0; // GLB's buffer 0 is its BIN chunk
            if (buffer.contains("uri") || glbChunk) {
                continue; // real fallback data: decoded anyway, and the data is ignored
            }
            const std::string where = "buffer " + std::to_string(b);
            out.placeholders[b] = unsignedMember(buffer, "byteLength", where, file, true);
            buffer["uri"] = PLACEHOLDER_URI;
            buffer["byteLength"] = 4;
            changed = true;
        }
    }
    if (Json* meshes = array("meshes")) {
        for (std::size_t m = 0; m < meshes->size() && m <= std::size_t(INT32_MAX); ++m) {
            Json& mesh = (*meshes)[m];
            if (!mesh.is_object() || !mesh.contains("primitives") ||
                !mesh["primitives"].is_array()) {
                continue;
            }
            Json& primitives = mesh["primitives"];
            for (std::size_t p = 0; p < primitives.size() && p <= std::size_t(INT32_MAX); ++p) {
                if (const Json* ext = extensionOf(primitives[p], DRACO)) {
                    out.draco.push_back(readDraco(primitives[p], *ext, int(m), int(p), file));
                    changed |= out.draco.back().indices != -1;
                }
            }
        }
    }
    return changed;
}

bool mentions(const unsigned char* text, std::size_t length, std::string_view word) {
    return std::string_view(reinterpret_cast<const char*>(text), length).find(word) !=
           std::string_view::npos;
}

} // namespace

CompressionPlan planDecompression(std::vector<unsigned char>& bytes, bool binary,
                                  const std::string& file) {
    CompressionPlan out;
    std::size_t jsonStart = 0, jsonLength = bytes.size();
    if (binary) {
        std::uint32_t chunkLength = 0;
        if (bytes.size() < 20 || std::memcmp(bytes.data() + 16, "JSON", 4) != 0) {
            return out; // tinygltf refuses the broken container
        }
        std::memcpy(&chunkLength, bytes.data() + 12, 4);
        if (chunkLength > bytes.size() - 20) {
            return out;
        }
        jsonStart = 20;
        jsonLength = chunkLength;
    }
    const unsigned char* text = bytes.data() + jsonStart;
    // Most files need neither; they are parsed once, by tinygltf.
    if (!mentions(text, jsonLength, "compression") &&
        !mentions(text, jsonLength, "extensionsRequired")) {
        return out;
    }
    Json doc = Json::parse(text, text + jsonLength, nullptr, false);
    if (!doc.is_object()) {
        return out;
    }
    checkRequired(doc, file);
    if (!plan(doc, binary, out, file)) {
        return out;
    }
    std::string json = doc.dump();
    if (!binary) {
        bytes.assign(json.begin(), json.end());
        return out;
    }
    json.append((4 - json.size() % 4) % 4, ' '); // GLB chunks are 4-byte aligned
    std::vector<unsigned char> rest(bytes.begin() + long(jsonStart + jsonLength), bytes.end());
    const std::uint32_t jsonChunk = std::uint32_t(json.size());
    const std::uint32_t total = std::uint32_t(20 + json.size() + rest.size());
    std::vector<unsigned char> glb(bytes.begin(), bytes.begin() + 8); // magic and version
    glb.resize(20);
    std::memcpy(glb.data() + 8, &total, 4);
    std::memcpy(glb.data() + 12, &jsonChunk, 4);
    std::memcpy(glb.data() + 16, "JSON", 4);
    glb.insert(glb.end(), json.begin(), json.end());
    glb.insert(glb.end(), rest.begin(), rest.end());
    bytes = std::move(glb);
    return out;
}

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
    for (const DracoPrimitive& d : plan.draco) {
        std::vector<int> accessors{d.indices};
        const auto& mesh = model.meshes[d.mesh].primitives[d.primitive];
        for (const auto& [name, id] : d.attributes) {
            const auto found = mesh.attributes.find(name);
            accessors.push_back(found == mesh.attributes.end() ? -1 : found->second);
        }
        for (int a : accessors) {
            if (a < 0 || std::size_t(a) >= model.accessors.size()) {
                continue; // decodeDraco names it
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
        views += view.extensions.count(MESHOPT_NAMES[0]) || view.extensions.count(MESHOPT_NAMES[1]);
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
