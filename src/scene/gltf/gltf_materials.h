// glTF materials to the GPU's Material records: metallic-roughness factors and textures,
// emission (KHR_materials_emissive_strength), alpha modes, KHR_materials_ior, _transmission,
// _specular (factors and textures), _clearcoat, _sheen and _volume (factors; their textures are
// ignored with a warning), and one TextureRef per texture use (sampler wrap and filter, sRGB for colour,
// TEXCOORD set, KHR_texture_transform). Images are decoded later (gltf_images.h).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// The glTF extensions the loader reads; any other is ignored with one warning, and refused
// when the file lists it in extensionsRequired.
bool isSupportedExtension(const std::string& name);

// What a primitive using a material must provide.
struct MaterialNeeds {
    bool uv0 = false;           // some texture samples TEXCOORD_0
    bool uv1 = false;           // ... or TEXCOORD_1
    int normalMapTexCoord = -1; // UV set that tangents follow, -1 without a normal map
};

struct MaterialTables {
    std::vector<Material> materials;   // one per glTF material
    std::vector<MaterialNeeds> needs;  // parallel to materials
    std::vector<TextureRef> refs;      // material texture fields index this
    std::vector<uint32_t> refImage;    // glTF image index of each ref
    std::vector<bool> imageUsed;       // per glTF image
};

// Fails (InputError) on out-of-range indices and values outside glTF's ranges; warns about
// what it ignores.
MaterialTables convertMaterials(const tinygltf::Model& model, const std::string& file);

// The default material for primitives without one (glTF: white, metallic 1, roughness 1 is
// the spec's default, but a grey Lambert-like surface is what users expect to see).
Material defaultMaterial();

} // namespace wf::gltf
