// KHR_materials_variants: the root's named variants and each primitive's mappings
// ({material, variants: [indices]}). A chosen variant is applied when the file is read: every
// primitive with a mapping for it takes the mapped material, the others keep their own, so a
// variant switches materials and nothing else (geometry, placements and lights are the same).
#pragma once
#include <string>
#include <vector>

namespace tinygltf {
class Model;
} // namespace tinygltf

namespace wf::gltf {

struct VariantChoice {
    std::vector<std::string> names; // the file's variants, in file order ("" kept for unnamed)
    int chosen = -1;                // index into names; -1: the primitives' own materials
};

// Reads the variants and chooses `variant` (a name, else a decimal index; "" chooses none),
// then rewrites each primitive's material to its mapping for the chosen one. Fails (InputError,
// one line) for an unknown variant, for `variant` given to a file without variants, and for a
// malformed mapping the chosen variant needs (a material or variant index out of range); a
// malformed mapping it does not need costs a warning.
VariantChoice applyMaterialVariant(tinygltf::Model& model, const std::string& file,
                                   const std::string& variant);

} // namespace wf::gltf
