// One TextureRef per texture use of a material: the image (EXT_texture_webp's, else the core
// `source`, which is also KHR_texture_basisu's PNG/JPEG fallback), the sampler's wrap modes and
// filter, sRGB for colour, the TEXCOORD set and KHR_texture_transform, for the core textureInfos
// and for those inside material extensions alike. Also the small JSON readers the material code
// shares. Images are decoded later (gltf_images.h).
#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "scene/gltf/gltf_materials.h"

namespace tinygltf {
class Value;
}

namespace wf::gltf {

using ExtensionObjects = std::map<std::string, tinygltf::Value>; // tinygltf::ExtensionMap

// A number member, `fallback` when absent, NaN when present but not a number (so that a range
// check refuses it).
double jsonNumber(const tinygltf::Value& object, const char* key, double fallback);
// An array member of `n` numbers, `fallback` when absent, NaNs when malformed.
std::vector<double> jsonNumbers(const tinygltf::Value& object, const char* key, size_t n,
                                std::vector<double> fallback);
// The named extension's object, or a null Value.
const tinygltf::Value& extensionIn(const ExtensionObjects& map, const char* name);

// KHR_texture_basisu is not warned about when a file uses it: its textures' fallback sources
// are read, and a texture without one is named once by TextureRefs. (Refused when required.)
bool isReadThroughFallbacks(const std::string& extension);

// Appends texture references to `tables` (refs, refImage, refDerived, imageUsed). Fails
// (InputError) on indices out of range and non-finite transforms, as for the core textures.
class TextureRefs {
public:
    TextureRefs(const tinygltf::Model& model, const std::string& file, MaterialTables& tables)
        : model_(model), file_(file), tables_(tables) {}

    // A core textureInfo (tinygltf parsed it): texture -1 is none. `slot` names it in messages.
    uint32_t core(int texture, int texCoord, const ExtensionObjects& extensions, bool srgb,
                  const std::string& slot, MaterialNeeds& needs);
    // A textureInfo member `key` of a material extension's object, with its own `texCoord` and
    // KHR_texture_transform. When `scale` is given, the textureInfo's `scale` (a normal map's)
    // is stored there (1 without one).
    uint32_t inExtension(const tinygltf::Value& extension, const char* key, bool srgb,
                         const std::string& material, MaterialNeeds& needs,
                         float* scale = nullptr);

private:
    const tinygltf::Model& model_;
    const std::string& file_;
    MaterialTables& tables_;
    bool basisuWarned_ = false;
};

} // namespace wf::gltf
