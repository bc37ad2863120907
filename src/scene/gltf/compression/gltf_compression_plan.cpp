// Step 1 of gltf_compression.h: the JSON before tinygltf. nlohmann/json is the parser
// tinygltf itself is built on, so the plan sees the document as tinygltf will.
#include "scene/gltf/compression/gltf_compression.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <set>
#include <string_view>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/io/gltf_buffer_streaming.h"
#include "scene/gltf/compression/gltf_codecs.h"
#include "scene/gltf/gltf_materials.h"

namespace wf::gltf {
namespace {

using Json = nlohmann::json;

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
        std::uint32_t total = 0, chunkLength = 0;
        if (bytes.size() < 20 || std::memcmp(bytes.data() + 16, "JSON", 4) != 0) {
            return out; // tinygltf refuses the broken container in its own words
        }
        std::memcpy(&total, bytes.data() + 8, 4);
        std::memcpy(&chunkLength, bytes.data() + 12, 4);
        if (total != bytes.size() || chunkLength > bytes.size() - 20) {
            return out; // a rewrite would mend the lengths tinygltf checks
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
    // The parser checked the UTF-8, so `replace` never fires; it only keeps dump() from throwing.
    std::string json = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (!binary) {
        bytes.assign(json.begin(), json.end());
        return out;
    }
    const std::size_t restStart = jsonStart + jsonLength;
    bytes = glbContainer(bytes.data(), std::move(json), bytes.data() + restStart,
                         bytes.size() - restStart);
    return out;
}

} // namespace wf::gltf
