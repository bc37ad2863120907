// Accessor -> bufferView -> buffer, each hop bounds-checked; element reads use memcpy because
// glTF allows strides and offsets that leave elements unaligned.
#include "scene/gltf_accessors.h"

#include <tiny_gltf.h>

#include <cmath>
#include <cstring>

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

// A checked accessor: `count` elements, `stride` bytes apart, all inside their buffer.
struct AccessorReader::Elements {
    const unsigned char* bytes = nullptr;
    size_t count = 0;
    size_t stride = 0;
    int componentType = 0;
};

AccessorReader::Elements AccessorReader::elements(int index, const std::string& role,
                                                  int type) const {
    checkIndex(file_, index, model_.accessors.size(), "accessor", role);
    const tinygltf::Accessor& acc = model_.accessors[index];
    const std::string name = "accessor " + std::to_string(index) + " (" + role + ")";
    const bool vec3 = type == TINYGLTF_TYPE_VEC3;
    if (acc.type != type) {
        fail(file_, name + " has the wrong type (" + (vec3 ? "VEC3" : "SCALAR") + " expected)");
    }
    if (acc.sparse.isSparse) {
        fail(file_, name + " is sparse, which is not supported");
    }
    if (acc.bufferView == -1) {
        fail(file_, name + " has no bufferView, which is not supported");
    }
    checkIndex(file_, acc.bufferView, model_.bufferViews.size(), "bufferView", name);
    const tinygltf::BufferView& view = model_.bufferViews[acc.bufferView];
    const std::string viewName = "bufferView " + std::to_string(acc.bufferView);
    checkIndex(file_, view.buffer, model_.buffers.size(), "buffer", viewName);
    const size_t bufferSize = model_.buffers[view.buffer].data.size();
    if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength) {
        fail(file_, viewName + " extends past the end of buffer " + std::to_string(view.buffer) +
                        " (" + std::to_string(bufferSize) + " bytes)");
    }
    const size_t elementSize = componentSize(acc.componentType) * (vec3 ? 3 : 1);
    const size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (elementSize == 0 || stride < elementSize) {
        fail(file_, name + ": bad componentType or byteStride smaller than one element");
    }
    // Written so that no term can overflow: the last element must end inside the view.
    const size_t length = view.byteLength;
    if (acc.count > 0 &&
        (acc.byteOffset > length || elementSize > length - acc.byteOffset ||
         (acc.count - 1) > (length - acc.byteOffset - elementSize) / stride)) {
        fail(file_, name + ": " + std::to_string(acc.count) + " elements extend past the end of " +
                        viewName + " (" + std::to_string(length) + " bytes)");
    }
    const unsigned char* base = model_.buffers[view.buffer].data.data() + view.byteOffset;
    return {base + acc.byteOffset, acc.count, stride, acc.componentType};
}

const std::vector<glm::vec3>& AccessorReader::positions(int accessor, const std::string& where) {
    auto cached = positionCache_.find(accessor);
    if (cached != positionCache_.end()) {
        return cached->second;
    }
    Elements data = elements(accessor, "POSITION of " + where, TINYGLTF_TYPE_VEC3);
    if (data.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        fail(file_, "accessor " + std::to_string(accessor) + " (POSITION of " + where +
                        ") must hold floats");
    }
    std::vector<glm::vec3> points(data.count);
    for (size_t i = 0; i < data.count; ++i) {
        float xyz[3];
        std::memcpy(xyz, data.bytes + i * data.stride, sizeof(xyz)); // may be unaligned
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
            fail(file_, "accessor " + std::to_string(accessor) + " (POSITION of " + where +
                            ") has a NaN or infinite coordinate in element " + std::to_string(i));
        }
        points[i] = glm::vec3(xyz[0], xyz[1], xyz[2]);
    }
    return positionCache_.emplace(accessor, std::move(points)).first->second;
}

std::vector<uint32_t> AccessorReader::indices(int accessor, size_t vertexCount,
                                              const std::string& where) {
    Elements data = elements(accessor, "indices of " + where, TINYGLTF_TYPE_SCALAR);
    const size_t size = componentSize(data.componentType);
    if (data.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        data.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        data.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        fail(file_, "accessor " + std::to_string(accessor) + " (indices of " + where +
                        ") must hold unsigned 8, 16 or 32-bit integers");
    }
    std::vector<uint32_t> out(data.count);
    for (size_t i = 0; i < data.count; ++i) {
        const unsigned char* p = data.bytes + i * data.stride;
        uint32_t u32 = 0;
        if (size == 1) {
            u32 = p[0];
        } else if (size == 2) {
            uint16_t u16 = 0;
            std::memcpy(&u16, p, 2); // little-endian file, little-endian host
            u32 = u16;
        } else {
            std::memcpy(&u32, p, 4);
        }
        if (u32 >= vertexCount) {
            fail(file_, "accessor " + std::to_string(accessor) + " (indices of " + where +
                            "): element " + std::to_string(i) + " is " + std::to_string(u32) +
                            ", but there are only " + std::to_string(vertexCount) + " vertices");
        }
        out[i] = u32;
    }
    return out;
}

} // namespace wf::gltf
