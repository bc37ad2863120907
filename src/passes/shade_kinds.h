// Shading split by material kind: each hit is binned by the kind of BSDF its material needs,
// and each kind present gets a shade pass compiled without the other kinds' code. On lavapipe
// every lane of an 8-wide subgroup runs all the code its shader holds, taken or not, so a
// diffuse hit in a scene with glass pays for the glass unless the two are shaded apart.
#pragma once
#include <cstdint>
#include <vector>

#include "shaders/types/scene_types.h"

namespace wf {

// Kinds in order of cost; the bit index in ShaderVariant::shadeKinds.
enum class ShadeKind : uint32_t {
    Diffuse = 0,  // Lambert only (WF_BSDF_DIFFUSE_ONLY): metallic, specular, transmission 0
    Specular = 1, // Dirac lobes only (WF_BSDF_DELTA_ONLY): smooth mirrors and glass, no NEE
    General = 2,  // everything else: the full glTF BSDF, layered where the scene has layers
};
constexpr uint32_t kShadeKinds = 3;

// --shade-split: Auto splits a scene of two or more kinds only where none is General (with
// the general kind present, binning in intersect cost as much as shading apart saved: the
// 4-material scaling scenes ran 6-9% slower, 5 alternations); On splits wherever two kinds
// or more are present; Off never does.
enum class ShadeSplit { Auto, On, Off };

// The kinds `split` gives a shade pass of their own where the scene holds `present`.
uint32_t shadeKindsFor(uint32_t present, ShadeSplit split);

// The kind whose variant shades every hit of `m` exactly as the general BSDF would. Texture
// factors multiply the material's factors, so zero factors stay zero and a factor of one
// stays one only without a texture.
ShadeKind shadeKind(const gpu_types::Material& m);

// Bit k set: some material is of kind k.
uint32_t shadeKindsPresent(const std::vector<gpu_types::Material>& materials);

// The kinds that get a shade pass where the scene holds `present` (bit k: kind k): none (0)
// below two kinds ("model no more than a scene needs": one pass, today's shaders), else those.
uint32_t shadeKindsFor(uint32_t present);

// Bins are the kinds of `kinds` in kind order: the bin of `kind` (which must be in it), and
// the bin that takes misses and sphere-light hits (the cheapest variant: specular, else
// diffuse, else general).
uint32_t shadeBinOf(uint32_t kinds, ShadeKind kind);
uint32_t lightHitBin(uint32_t kinds);

} // namespace wf
