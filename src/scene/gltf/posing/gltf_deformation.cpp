// Morph targets and skins of one primitive (glTF 2.0 sections 3.7.2.2, 3.7.3).
#include "scene/gltf/posing/gltf_deformation.h"

#include <tiny_gltf.h>

#include "scene/animation/deformation.h"

namespace wf::gltf {

namespace {

int attributeOf(const std::map<std::string, int>& attributes, const char* key) {
    auto found = attributes.find(key);
    return found == attributes.end() ? -1 : found->second;
}

// One target's delta array for an attribute of `count` vertices, `components` wide (TANGENT
// deltas are VEC3 and widen to 4 with a zero w, so the handedness stays).
std::vector<float> targetDeltas(AccessorReader& reader, const std::string& file, int accessor,
                                const std::string& name, std::size_t count, int components) {
    const int read = components == 4 ? 3 : components;
    const FloatArray& d = reader.floats(accessor, name, read);
    if (d.count != count)
        fail(file, name + " has " + std::to_string(d.count) + " elements but POSITION has " +
                       std::to_string(count));
    if (read == components)
        return d.values;
    std::vector<float> wide(count * 4, 0.0f);
    for (std::size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c)
            wide[4 * i + c] = d.values[3 * i + c];
    return wide;
}

void applyTargets(AccessorReader& reader, const std::string& file,
                  const tinygltf::Primitive& primitive, const std::string& where,
                  const std::vector<double>& weights, const char* key, FloatArray* array,
                  int components) {
    if (!array)
        return;
    std::vector<std::vector<float>> owned(primitive.targets.size());
    std::vector<const float*> deltas(primitive.targets.size(), nullptr);
    for (std::size_t t = 0; t < primitive.targets.size(); ++t) {
        const int accessor = attributeOf(primitive.targets[t], key);
        if (accessor == -1 || t >= weights.size() || weights[t] == 0.0)
            continue;
        owned[t] = targetDeltas(reader, file, accessor,
                                std::string(key) + " of morph target " + std::to_string(t) +
                                    " of " + where,
                                array->count, components);
        deltas[t] = owned[t].data();
    }
    anim::applyMorphTargets(array->values, deltas, weights);
}

// JOINTS_n and WEIGHTS_n of one set, checked: unsigned 8/16-bit joints below `joints`, float
// or normalized unsigned weights, one element per vertex.
void readInfluences(AccessorReader& reader, const std::string& file,
                    const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                    const std::string& where, int set, std::size_t count, std::size_t joints,
                    std::vector<float>& jointOut, std::vector<float>& weightOut) {
    const std::string j = "JOINTS_" + std::to_string(set), w = "WEIGHTS_" + std::to_string(set);
    const int ja = attributeOf(primitive.attributes, j.c_str());
    const int wa = attributeOf(primitive.attributes, w.c_str());
    if (ja == -1 && wa == -1)
        return;
    if (ja == -1 || wa == -1)
        fail(file, where + ": " + (ja == -1 ? w + " without " + j : j + " without " + w));
    checkIndex(file, ja, model.accessors.size(), "accessor", j + " of " + where);
    const tinygltf::Accessor& jacc = model.accessors[ja];
    if ((jacc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         jacc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) || jacc.normalized)
        fail(file, where + ": " + j + " must hold unsigned 8 or 16-bit integers, not normalized");
    checkIndex(file, wa, model.accessors.size(), "accessor", w + " of " + where);
    const tinygltf::Accessor& wacc = model.accessors[wa];
    if (wacc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !wacc.normalized)
        fail(file, where + ": " + w + " must hold floats or normalized unsigned integers");
    const FloatArray& ji = reader.floats(ja, j + " of " + where, 4);
    const FloatArray& wi = reader.floats(wa, w + " of " + where, 4);
    if (ji.count != count || wi.count != count)
        fail(file, where + ": " + j + " and " + w + " need " + std::to_string(count) +
                       " elements, one per vertex (they have " + std::to_string(ji.count) +
                       " and " + std::to_string(wi.count) + ")");
    for (std::size_t i = 0; i < ji.values.size(); ++i) {
        if (wi.values[i] < 0.0f)
            fail(file, where + ": " + w + " has a negative weight at vertex " +
                           std::to_string(i / 4));
        if (ji.values[i] >= float(joints) && wi.values[i] != 0.0f)
            fail(file, where + ": " + j + " names joint " + std::to_string(int(ji.values[i])) +
                           " at vertex " + std::to_string(i / 4) + ", but the skin has " +
                           std::to_string(joints));
    }
    // Interleave into 4 or 8 influences per vertex.
    const std::size_t width = jointOut.empty() ? 4 : 8;
    std::vector<float> jo(count * width), wo(count * width);
    for (std::size_t v = 0; v < count; ++v) {
        for (std::size_t k = 0; k < width; ++k) {
            const bool second = k >= 4;
            const std::size_t c = k % 4;
            const bool fromOld = width == 8 && !second;
            jo[v * width + k] = fromOld ? jointOut[v * 4 + c] : ji.values[v * 4 + c];
            wo[v * width + k] = fromOld ? weightOut[v * 4 + c] : wi.values[v * 4 + c];
            if (wo[v * width + k] == 0.0f)
                jo[v * width + k] = 0.0f; // an unused slot may name any joint
        }
    }
    jointOut = std::move(jo);
    weightOut = std::move(wo);
}

} // namespace

void deformPrimitive(AccessorReader& reader, const std::string& file,
                     const tinygltf::Primitive& primitive, const std::string& where,
                     const Deformation& deformation, FloatArray& points, FloatArray* normals,
                     FloatArray* tangents) {
    if (!deformation.morphWeights.empty() && !primitive.targets.empty()) {
        applyTargets(reader, file, primitive, where, deformation.morphWeights, "POSITION",
                     &points, 3);
        applyTargets(reader, file, primitive, where, deformation.morphWeights, "NORMAL",
                     normals, 3);
        applyTargets(reader, file, primitive, where, deformation.morphWeights, "TANGENT",
                     tangents, 4);
    }
    if (deformation.jointMatrices.empty() || points.count == 0)
        return;
    std::vector<float> joints, weights;
    const tinygltf::Model& model = reader.model();
    for (int set = 0; set < 2; ++set)
        readInfluences(reader, file, model, primitive, where, set, points.count,
                       deformation.jointMatrices.size(), joints, weights);
    if (joints.empty())
        fail(file, where + ": its node has a skin but it has no JOINTS_0 and WEIGHTS_0");
    anim::skinVertices(deformation.jointMatrices, joints.data(), weights.data(),
                       joints.size() / points.count, points.count, points.values.data(),
                       normals ? normals->values.data() : nullptr,
                       tangents ? tangents->values.data() : nullptr);
}

std::vector<glm::dmat4> jointMatrices(const tinygltf::Model& model, const std::string& file,
                                      AccessorReader& reader, int skinIndex,
                                      const std::vector<glm::dmat4>& nodeWorld) {
    const tinygltf::Skin& skin = model.skins[skinIndex];
    const std::string name = "skin " + std::to_string(skinIndex);
    if (skin.joints.empty())
        fail(file, name + " has no joints");
    std::vector<glm::dmat4> out(skin.joints.size(), glm::dmat4(1.0));
    if (skin.inverseBindMatrices != -1) {
        checkIndex(file, skin.inverseBindMatrices, model.accessors.size(),
                   "inverseBindMatrices accessor", name);
        if (model.accessors[skin.inverseBindMatrices].componentType !=
            TINYGLTF_COMPONENT_TYPE_FLOAT)
            fail(file, name + ": inverseBindMatrices must hold float MAT4s");
        const FloatArray& ibm =
            reader.floats(skin.inverseBindMatrices, "inverseBindMatrices of " + name, 16);
        if (ibm.count < skin.joints.size())
            fail(file, name + ": inverseBindMatrices has " + std::to_string(ibm.count) +
                           " matrices for " + std::to_string(skin.joints.size()) + " joints");
        for (std::size_t j = 0; j < skin.joints.size(); ++j)
            for (int i = 0; i < 16; ++i)
                out[j][i / 4][i % 4] = ibm[j][i]; // column-major in glTF and glm alike
    }
    for (std::size_t j = 0; j < skin.joints.size(); ++j) {
        checkIndex(file, skin.joints[j], model.nodes.size(), "joint node", name);
        out[j] = nodeWorld[skin.joints[j]] * out[j];
    }
    return out;
}

} // namespace wf::gltf
