// Accessor -> bufferView -> buffer, each hop bounds-checked; element reads use memcpy because
// glTF allows strides and offsets that leave elements unaligned.
#include "scene/gltf/gltf_accessors.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <iostream>

#include "errors.h"

namespace wf::gltf {
namespace {

size_t componentSize(int componentType) {
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
    case TINYGLTF_COMPONENT_TYPE_INT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
    default: return 0;
    }
}

bool allowed(unsigned mask, int componentType) {
    const int bit = componentType - TINYGLTF_COMPONENT_TYPE_BYTE;
    return bit >= 0 && bit < 32 && (mask >> bit & 1u) != 0;
}

// glTF's rules for integer attributes: normalized values map onto [0, 1] or [-1, 1] (the most
// negative signed value clamps to -1), others convert as plain numbers.
float readFloatComponent(const unsigned char* p, int type, bool normalized) {
    switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
        const float v = float(static_cast<int8_t>(p[0]));
        return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? p[0] / 255.0f : float(p[0]);
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
        int16_t s;
        std::memcpy(&s, p, 2);
        return normalized ? std::max(float(s) / 32767.0f, -1.0f) : float(s);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t u;
        std::memcpy(&u, p, 2);
        return normalized ? float(u) / 65535.0f : float(u);
    }
    default: {
        float f;
        std::memcpy(&f, p, 4);
        return f;
    }
    }
}

uint32_t readUintComponent(const unsigned char* p, int type, bool) {
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
        return p[0];
    }
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        uint16_t u;
        std::memcpy(&u, p, 2); // little-endian file, little-endian host
        return u;
    }
    uint32_t u;
    std::memcpy(&u, p, 4);
    return u;
}

} // namespace

void fail(const std::string& file, const std::string& problem) {
    throw InputError(file + ": " + problem);
}

void checkIndex(const std::string& file, int index, size_t size, const std::string& what,
                const std::string& by) {
    if (index < 0 || size_t(index) >= size) {
        fail(file, by + " refers to " + what + " " + std::to_string(index) +
                       ", which does not exist (the file has " + std::to_string(size) + ")");
    }
}

namespace {
thread_local std::vector<std::string>* activeSink = nullptr;
}

WarningSink::WarningSink() : previous_(activeSink) { activeSink = &lines_; }
WarningSink::~WarningSink() { activeSink = previous_; }

void warn(const std::string& file, const std::string& problem, const char* kind) {
    std::string line = std::string(kind) + ": " + file + ": " + problem;
    if (activeSink) {
        activeSink->push_back(std::move(line));
    } else {
        std::cerr << line << "\n";
    }
}

// A checked dense accessor: `count` elements, `stride` bytes apart, all inside their buffer;
// `bytes` is null for an accessor without bufferView (all zeros before sparse values).
struct AccessorReader::Dense {
    const unsigned char* bytes = nullptr;
    size_t count = 0;
    size_t stride = 0;
    size_t elementSize = 0;
    int componentType = 0;
    bool normalized = false;
};

// Checks that `count` elements of `elementSize`, `stride` apart from `offset`, lie inside
// bufferView `viewIndex`, and returns the first element's address.
static const unsigned char* checkedRange(const tinygltf::Model& model, const std::string& file,
                                         int viewIndex, size_t offset, size_t elementSize,
                                         size_t stride, size_t count, const std::string& name) {
    checkIndex(file, viewIndex, model.bufferViews.size(), "bufferView", name);
    const tinygltf::BufferView& view = model.bufferViews[viewIndex];
    const std::string viewName = "bufferView " + std::to_string(viewIndex);
    checkIndex(file, view.buffer, model.buffers.size(), "buffer", viewName);
    const size_t bufferSize = model.buffers[view.buffer].data.size();
    if (bufferSize == 0 && view.byteLength > 0) { // gltf_buffer_streaming's buffer without uri
        fail(file, name + " reads buffer " + std::to_string(view.buffer) +
                       ", which has no data (no uri, and not a .glb's BIN chunk)");
    }
    if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength) {
        fail(file, viewName + " extends past the end of buffer " + std::to_string(view.buffer) +
                       " (" + std::to_string(bufferSize) + " bytes)");
    }
    // Written so that no term can overflow: the last element must end inside the view.
    const size_t length = view.byteLength;
    if (count > 0 && (offset > length || elementSize > length - offset ||
                      (count - 1) > (length - offset - elementSize) / stride)) {
        fail(file, name + ": " + std::to_string(count) + " elements extend past the end of " +
                       viewName + " (" + std::to_string(length) + " bytes)");
    }
    return model.buffers[view.buffer].data.data() + view.byteOffset + offset;
}

AccessorReader::Dense AccessorReader::dense(int index, const std::string& name,
                                            unsigned allowedTypes, int components) {
    const tinygltf::Accessor& acc = model_.accessors[index];
    if (tinygltf::GetNumComponentsInType(uint32_t(acc.type)) != components) {
        const std::string expected = components == 1    ? "SCALAR"
                                     : components == 16 ? "MAT4"
                                                        : "VEC" + std::to_string(components);
        fail(file_, name + " has the wrong type (" + expected + " expected)");
    }
    if (!allowed(allowedTypes, acc.componentType)) {
        fail(file_, name + " has componentType " + std::to_string(acc.componentType) +
                        ", which is not allowed here");
    }
    const bool isFloat = acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    if (acc.normalized && (isFloat || acc.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        fail(file_, name + " is normalized, which only 8 and 16-bit integers may be");
    }
    if (acc.count > MAX_ACCESSOR_ELEMENTS) {
        fail(file_, name + " has " + std::to_string(acc.count) + " elements, over the limit of " +
                        std::to_string(MAX_ACCESSOR_ELEMENTS));
    }
    Dense d;
    d.count = acc.count;
    d.componentType = acc.componentType;
    d.normalized = acc.normalized;
    d.elementSize = componentSize(acc.componentType) * size_t(components);
    d.stride = d.elementSize;
    if (acc.bufferView == -1) {
        if (!acc.sparse.isSparse) { // allowed by glTF, but then every element is zero
            warn(file_, name + " has no bufferView and no sparse values: all zeros");
        }
        return d;
    }
    checkIndex(file_, acc.bufferView, model_.bufferViews.size(), "bufferView", name);
    const size_t byteStride = model_.bufferViews[acc.bufferView].byteStride;
    if (byteStride != 0) {
        // glTF: 4 to 252, a multiple of 4; smaller than an element would overlap elements.
        if (byteStride < d.elementSize || byteStride > 252 || byteStride % 4 != 0) {
            fail(file_, name + ": byteStride " + std::to_string(byteStride) +
                            " is invalid for elements of " + std::to_string(d.elementSize) +
                            " bytes");
        }
        d.stride = byteStride;
    }
    d.bytes = checkedRange(model_, file_, acc.bufferView, acc.byteOffset, d.elementSize, d.stride,
                           d.count, name);
    return d;
}

// Reads every element (dense part, then sparse substitutions) through `readComponent`.
template <class T, class Read>
std::vector<T> AccessorReader::read(int index, const std::string& name, unsigned allowedTypes,
                                    int components, Read readComponent) {
    Dense d = dense(index, name, allowedTypes, components);
    const size_t componentBytes = d.elementSize / size_t(components);
    std::vector<T> out(d.count * size_t(components), T(0));
    if (d.bytes) {
        for (size_t i = 0; i < d.count; ++i) {
            const unsigned char* element = d.bytes + i * d.stride;
            for (int c = 0; c < components; ++c) {
                out[i * components + c] =
                    readComponent(element + c * componentBytes, d.componentType, d.normalized);
            }
        }
    }
    elementsRead_ += d.count;
    const tinygltf::Accessor& acc = model_.accessors[index];
    if (!acc.sparse.isSparse) {
        return out;
    }
    const auto& sparse = acc.sparse;
    const std::string sparseName = name + " (sparse)";
    if (sparse.count < 1 || size_t(sparse.count) > d.count || sparse.indices.byteOffset < 0 ||
        sparse.values.byteOffset < 0) {
        fail(file_, sparseName + ": count must lie in [1, " + std::to_string(d.count) +
                        "] and offsets be non-negative");
    }
    const int indexType = sparse.indices.componentType;
    if (!allowed(INDEX_TYPES, indexType)) {
        fail(file_, sparseName + ": indices must be unsigned 8, 16 or 32-bit integers");
    }
    const size_t count = size_t(sparse.count);
    const size_t indexSize = componentSize(indexType);
    const unsigned char* indices =
        checkedRange(model_, file_, sparse.indices.bufferView, size_t(sparse.indices.byteOffset),
                     indexSize, indexSize, count, sparseName + " indices");
    const unsigned char* values =
        checkedRange(model_, file_, sparse.values.bufferView, size_t(sparse.values.byteOffset),
                     d.elementSize, d.elementSize, count, sparseName + " values");
    int64_t previous = -1;
    for (size_t k = 0; k < count; ++k) {
        const uint32_t target = readUintComponent(indices + k * indexSize, indexType, false);
        if (target >= d.count || int64_t(target) <= previous) { // glTF: strictly increasing
            fail(file_, sparseName + ": index " + std::to_string(target) + " at " +
                            std::to_string(k) + " is out of range or not increasing");
        }
        previous = target;
        for (int c = 0; c < components; ++c) {
            out[size_t(target) * components + c] = readComponent(
                values + k * d.elementSize + c * componentBytes, d.componentType, d.normalized);
        }
    }
    return out;
}

const FloatArray& AccessorReader::floats(int accessor, const std::string& role, int components) {
    checkIndex(file_, accessor, model_.accessors.size(), "accessor", role);
    const long long key = (long long)accessor * 32 + components; // components <= 16
    auto cached = floatCache_.find(key);
    if (cached != floatCache_.end()) {
        return cached->second;
    }
    const std::string name = "accessor " + std::to_string(accessor) + " (" + role + ")";
    FloatArray array;
    array.components = components;
    array.values = read<float>(accessor, name, ATTRIBUTE_TYPES, components, readFloatComponent);
    array.count = array.values.size() / size_t(components);
    for (size_t i = 0; i < array.values.size(); ++i) {
        if (!std::isfinite(array.values[i])) {
            fail(file_, name + " has a NaN or infinite value in element " +
                            std::to_string(i / size_t(components)));
        }
    }
    return floatCache_.emplace(key, std::move(array)).first->second;
}

std::vector<uint32_t> AccessorReader::indices(int accessor, size_t vertexCount,
                                              const std::string& where) {
    const std::string role = "indices of " + where;
    checkIndex(file_, accessor, model_.accessors.size(), "accessor", role);
    const std::string name = "accessor " + std::to_string(accessor) + " (" + role + ")";
    if (model_.accessors[accessor].normalized) {
        fail(file_, name + " must not be normalized");
    }
    std::vector<uint32_t> out = read<uint32_t>(accessor, name, INDEX_TYPES, 1, readUintComponent);
    for (size_t i = 0; i < out.size(); ++i) {
        if (out[i] >= vertexCount) {
            fail(file_, name + ": element " + std::to_string(i) + " is " +
                            std::to_string(out[i]) + ", but there are only " +
                            std::to_string(vertexCount) + " vertices");
        }
    }
    return out;
}

int accessorWithoutData(const tinygltf::Model& model, const tinygltf::Primitive& primitive) {
    std::vector<int> accessors{primitive.indices};
    for (const auto& [name, index] : primitive.attributes)
        accessors.push_back(index);
    for (const auto& target : primitive.targets)
        for (const auto& [name, index] : target)
            accessors.push_back(index);
    for (int a : accessors) {
        if (a < 0 || std::size_t(a) >= model.accessors.size())
            continue;
        const int view = model.accessors[a].bufferView;
        if (view < 0 || std::size_t(view) >= model.bufferViews.size())
            continue;
        const int buffer = model.bufferViews[view].buffer;
        if (buffer >= 0 && std::size_t(buffer) < model.buffers.size() &&
            model.buffers[buffer].data.empty() && model.buffers[buffer].uri.empty())
            return a;
    }
    return -1;
}

} // namespace wf::gltf
