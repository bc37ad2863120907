// EXT_mesh_gpu_instancing's attributes, checked from the JSON and the accessors' headers first
// (gpuInstanceCount, before anything is read), then read as floats by the accessor reader.
#include "scene/gltf/gltf_gpu_instancing.h"

#include <tiny_gltf.h>

#include <cmath>

#include "scene/gltf/gltf_scene_limits.h"
#include "scene/gltf/posing/gltf_node_pose.h"

namespace wf::gltf {
namespace {

constexpr const char* kExtension = "EXT_mesh_gpu_instancing";

struct Attribute {
    const char* name;
    int components;
    unsigned types; // ComponentMask bits; integers only normalized
};
constexpr Attribute kTranslation{"TRANSLATION", 3, FLOAT_BIT};
constexpr Attribute kRotation{"ROTATION", 4, FLOAT_BIT | BYTE_BIT | SHORT_BIT};
constexpr Attribute kScale{"SCALE", 3, FLOAT_BIT};

std::string nodeName(int nodeIndex) { return "node " + std::to_string(nodeIndex); }

// The attributes object of the node's extension, or null where the node has none.
const tinygltf::Value* attributesOf(const tinygltf::Model& model, const std::string& file,
                                    int nodeIndex) {
    const tinygltf::Node& node = model.nodes[nodeIndex];
    auto ext = node.extensions.find(kExtension);
    if (ext == node.extensions.end())
        return nullptr;
    const tinygltf::Value& value = ext->second;
    if (!value.IsObject() || !value.Has("attributes") || !value.Get("attributes").IsObject())
        fail(file, nodeName(nodeIndex) + ": " + kExtension + " needs an \"attributes\" object");
    return &value.Get("attributes");
}

// The accessor index attribute `key` names, checked to exist.
int accessorOf(const tinygltf::Model& model, const std::string& file, int nodeIndex,
               const tinygltf::Value& attributes, const std::string& key) {
    const tinygltf::Value& v = attributes.Get(key);
    const double index = v.IsNumber() ? v.GetNumberAsDouble() : -1.0;
    const std::string by = nodeName(nodeIndex) + "'s " + kExtension + " " + key;
    if (!(index >= 0.0 && index < double(model.accessors.size())) || index != std::floor(index))
        fail(file, by + " refers to an accessor that does not exist (the file has " +
                       std::to_string(model.accessors.size()) + ")");
    return int(index);
}

void checkType(const tinygltf::Model& model, const std::string& file, int nodeIndex,
               int accessor, const Attribute& attribute) {
    const tinygltf::Accessor& acc = model.accessors[accessor];
    const int bit = acc.componentType - TINYGLTF_COMPONENT_TYPE_BYTE;
    const bool isFloat = acc.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT;
    const bool typeOk = tinygltf::GetNumComponentsInType(uint32_t(acc.type)) ==
                            attribute.components &&
                        acc.type != TINYGLTF_TYPE_MAT2; // MAT2 has 4 components too
    const bool componentOk = bit >= 0 && bit < 32 && (attribute.types >> bit & 1u) != 0 &&
                             (isFloat ? !acc.normalized : acc.normalized);
    if (!typeOk || !componentOk) {
        const std::string expected =
            attribute.components == 4 ? "VEC4 of FLOAT, or of normalized BYTE or SHORT"
                                      : "VEC3 of FLOAT";
        fail(file, nodeName(nodeIndex) + "'s " + kExtension + " " + attribute.name +
                       " (accessor " + std::to_string(accessor) + ") must be " + expected);
    }
}

const Attribute* known(const std::string& key) {
    for (const Attribute* a : {&kTranslation, &kRotation, &kScale})
        if (key == a->name)
            return a;
    return nullptr;
}

// gpuInstanceCount, saying what it ignores only where `report` (once per node and load).
std::size_t countInstances(const tinygltf::Model& model, const std::string& file, int nodeIndex,
                           bool report) {
    const tinygltf::Value* attributes = attributesOf(model, file, nodeIndex);
    if (!attributes)
        return 0;
    const std::string name = nodeName(nodeIndex);
    std::size_t count = 0;
    std::string first;
    for (const std::string& key : attributes->Keys()) {
        const Attribute* attribute = known(key);
        if (!attribute && (key.empty() || key[0] != '_')) {
            if (report)
                warn(file, name + ": ignoring " + kExtension + " attribute " + key +
                               " (not one of TRANSLATION, ROTATION, SCALE)");
            continue;
        }
        const int accessor = accessorOf(model, file, nodeIndex, *attributes, key);
        if (attribute)
            checkType(model, file, nodeIndex, accessor, *attribute);
        const std::size_t n = model.accessors[accessor].count;
        if (first.empty()) {
            count = n;
            first = key;
        } else if (n != count) {
            fail(file, name + "'s " + kExtension + " attributes differ in count (" + first +
                           " has " + std::to_string(count) + ", " + key + " " +
                           std::to_string(n) + ")");
        }
    }
    if (first.empty()) {
        if (report)
            warn(file, name + ": " + kExtension + " has no attributes; its mesh is placed once");
        return 0;
    }
    if (count == 0 || count > kMaxInstances)
        fail(file, name + "'s " + kExtension + " places " + std::to_string(count) +
                       " instances; 1 to " + std::to_string(kMaxInstances) + " are allowed");
    return count;
}

} // namespace

std::size_t gpuInstanceCount(const tinygltf::Model& model, const std::string& file,
                             int nodeIndex) {
    return countInstances(model, file, nodeIndex, true);
}

GpuInstances::GpuInstances(const tinygltf::Model& model, const std::string& file,
                           AccessorReader& reader, int nodeIndex) {
    count_ = countInstances(model, file, nodeIndex, false);
    if (count_ == 0)
        return;
    const tinygltf::Value& attributes = *attributesOf(model, file, nodeIndex);
    const std::string name = nodeName(nodeIndex);
    auto read = [&](const Attribute& a) -> const FloatArray* {
        if (!attributes.Has(a.name))
            return nullptr;
        const int accessor = accessorOf(model, file, nodeIndex, attributes, a.name);
        // Non-finite values fail here, naming the accessor and element.
        return &reader.floats(accessor, name + "'s instance " + a.name, a.components);
    };
    translation_ = read(kTranslation);
    rotation_ = read(kRotation);
    scale_ = read(kScale);
    if (rotation_)
        for (std::size_t i = 0; i < count_; ++i) {
            const float* q = (*rotation_)[i];
            const double len = std::sqrt(double(q[0]) * q[0] + double(q[1]) * q[1] +
                                         double(q[2]) * q[2] + double(q[3]) * q[3]);
            if (!(len > 0.0) || !std::isfinite(len))
                fail(file, name + "'s instance " + std::to_string(i) +
                               ": ROTATION is not a usable quaternion");
        }
}

// The arithmetic of nodeLocalTransform's T, R, S branch, so an instance lands exactly where a
// child node with the same numbers would.
glm::dmat4 GpuInstances::transform(std::size_t i) const {
    glm::dmat4 m(1.0);
    if (translation_) {
        const float* t = (*translation_)[i];
        m[3] = glm::dvec4(t[0], t[1], t[2], 1.0);
    }
    if (rotation_) {
        const double r[4] = {(*rotation_)[i][0], (*rotation_)[i][1], (*rotation_)[i][2],
                             (*rotation_)[i][3]};
        const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
        m = m * rotationMatrix(r[0] / len, r[1] / len, r[2] / len, r[3] / len);
    }
    if (scale_) {
        const float* s = (*scale_)[i];
        m = m * glm::dmat4(glm::dvec4(s[0], 0, 0, 0), glm::dvec4(0, s[1], 0, 0),
                           glm::dvec4(0, 0, s[2], 0), glm::dvec4(0, 0, 0, 1));
    }
    return m;
}

} // namespace wf::gltf
