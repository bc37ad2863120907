// glTF materials to the GPU's Material records: metallic-roughness factors and textures,
// emission (KHR_materials_emissive_strength), alpha modes, KHR_materials_ior, _transmission,
// _specular, _clearcoat, _sheen, _volume, _iridescence, _anisotropy and _diffuse_transmission
// (factors and textures), the archived KHR_materials_pbrSpecularGlossiness (mapped onto the
// same BSDF: docs/gltf.md), and one TextureRef per texture use (gltf_texture_refs.h). Images
// are decoded later (gltf_images.h).
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
    int normalMapTexCoord = -1; // UV set of the tangent frames (normal map, anisotropy); -1: none
};

// An image made at load from a decoded glTF image (KHR_materials_pbrSpecularGlossiness): a
// metallic-roughness texture whose G is 1 - glossinessFactor x the source's A (roughness, with
// the material's roughness factor 1), B 0 (metallic) and R, A 1.
struct RoughnessFromGlossiness {
    uint32_t image;         // glTF image index of the specularGlossinessTexture
    float glossinessFactor;
};

struct MaterialTables {
    std::vector<Material> materials;   // one per glTF material
    std::vector<MaterialNeeds> needs;  // parallel to materials
    std::vector<TextureRef> refs;      // material texture fields index this
    std::vector<uint32_t> refImage;    // glTF image index of each ref
    std::vector<int32_t> refDerived;   // per ref: index in `derived`, which it reads instead of
                                       // refImage (the source), or -1
    std::vector<RoughnessFromGlossiness> derived;
    std::vector<bool> imageUsed;       // per glTF image
};

// Fails (InputError) on out-of-range indices and values outside glTF's ranges; warns about
// what it ignores.
MaterialTables convertMaterials(const tinygltf::Model& model, const std::string& file);

// Every texture field of a material (WF_NO_TEXTURE or an index into the texture references),
// base colour first, for code that drops or remaps them all.
std::vector<uint32_t*> textureFields(Material& m);

// The default material for primitives without one (glTF: white, metallic 1, roughness 1 is
// the spec's default, but a grey Lambert-like surface is what users expect to see).
Material defaultMaterial();

} // namespace wf::gltf
