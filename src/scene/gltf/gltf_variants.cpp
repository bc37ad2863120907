// KHR_materials_variants, read from tinygltf's extension values: nothing in them is trusted.
#include "scene/gltf/gltf_variants.h"

#include <tiny_gltf.h>

#include <cmath>

#include "scene/gltf/gltf_accessors.h"

namespace wf::gltf {
namespace {

constexpr const char* kExtension = "KHR_materials_variants";

// A JSON number that is a whole index in [0, size), else -1.
int indexIn(const tinygltf::Value& v, std::size_t size) {
    if (!v.IsNumber())
        return -1;
    const double d = v.GetNumberAsDouble();
    return d >= 0.0 && d < double(size) && d == std::floor(d) ? int(d) : -1;
}

std::vector<std::string> variantNames(const tinygltf::Model& model, const std::string& file) {
    std::vector<std::string> names;
    auto ext = model.extensions.find(kExtension);
    if (ext == model.extensions.end())
        return names;
    const tinygltf::Value& root = ext->second;
    if (!root.IsObject() || !root.Has("variants") || !root.Get("variants").IsArray()) {
        warn(file, std::string(kExtension) + " has no \"variants\" array: its variants are "
                                             "ignored");
        return names;
    }
    const tinygltf::Value& list = root.Get("variants");
    for (std::size_t i = 0; i < list.ArrayLen(); ++i) {
        const tinygltf::Value& v = list.Get(int(i));
        names.push_back(v.IsObject() && v.Has("name") && v.Get("name").IsString()
                            ? v.Get("name").Get<std::string>()
                            : std::string());
    }
    return names;
}

int resolve(const std::vector<std::string>& names, const std::string& file,
            const std::string& variant) {
    if (variant.empty())
        return -1;
    const std::string flag = "--variant " + variant + ": ";
    if (names.empty())
        fail(file, flag + "the file has no variants (no " + kExtension + ")");
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == variant)
            return int(i);
    const bool digits = variant.find_first_not_of("0123456789") == std::string::npos;
    if (digits && variant.size() < 10 && std::stoul(variant) < names.size())
        return int(std::stoul(variant));
    std::string list;
    for (std::size_t i = 0; i < names.size(); ++i)
        list += (i ? ", " : "") + std::to_string(i) + " '" + names[i] + "'";
    fail(file, flag + "no such variant (the file has " + list + ")");
}

} // namespace

VariantChoice applyMaterialVariant(tinygltf::Model& model, const std::string& file,
                                   const std::string& variant) {
    VariantChoice choice;
    choice.names = variantNames(model, file);
    choice.chosen = resolve(choice.names, file, variant);
    const std::size_t materials = model.materials.size();
    for (std::size_t m = 0; m < model.meshes.size(); ++m) {
        for (std::size_t p = 0; p < model.meshes[m].primitives.size(); ++p) {
            tinygltf::Primitive& primitive = model.meshes[m].primitives[p];
            auto ext = primitive.extensions.find(kExtension);
            if (ext == primitive.extensions.end())
                continue;
            const std::string where = "mesh " + std::to_string(m) + " primitive " +
                                      std::to_string(p) + "'s " + kExtension;
            const tinygltf::Value& value = ext->second;
            if (!value.IsObject() || !value.Has("mappings") || !value.Get("mappings").IsArray()) {
                warn(file, where + " has no \"mappings\" array: ignored");
                continue;
            }
            const tinygltf::Value& mappings = value.Get("mappings");
            int mapped = -1; // the material for the chosen variant
            for (std::size_t k = 0; k < mappings.ArrayLen(); ++k) {
                const tinygltf::Value& mapping = mappings.Get(int(k));
                const std::string at = where + " mapping " + std::to_string(k);
                if (!mapping.IsObject() || !mapping.Has("variants") ||
                    !mapping.Get("variants").IsArray()) {
                    warn(file, at + " has no \"variants\" array: ignored");
                    continue;
                }
                const tinygltf::Value& variants = mapping.Get("variants");
                bool forChosen = false;
                for (std::size_t v = 0; v < variants.ArrayLen(); ++v) {
                    const int index = indexIn(variants.Get(int(v)), choice.names.size());
                    if (index < 0)
                        warn(file, at + " names a variant that does not exist (the file has " +
                                       std::to_string(choice.names.size()) + "): ignored");
                    forChosen |= index >= 0 && index == choice.chosen;
                }
                const int material =
                    mapping.Has("material") ? indexIn(mapping.Get("material"), materials) : -1;
                if (material < 0) {
                    const std::string problem =
                        at + " refers to a material that does not exist (the file has " +
                        std::to_string(materials) + ")";
                    if (forChosen)
                        fail(file, problem);
                    warn(file, problem + ": ignored");
                    continue;
                }
                if (forChosen && mapped < 0)
                    mapped = material;
            }
            if (mapped >= 0)
                primitive.material = mapped;
        }
    }
    return choice;
}

} // namespace wf::gltf
