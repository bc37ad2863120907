#include "passes/shade_kinds.h"

#include <algorithm>
#include <bit>

namespace wf {

ShadeKind shadeKind(const gpu_types::Material& m) {
    const bool layered = m.clearcoat > 0.0f ||
                         std::max({m.sheenColor.x, m.sheenColor.y, m.sheenColor.z}) > 0.0f;
    if (layered)
        return ShadeKind::General;
    if (m.metallic <= 0.0f && m.specular <= 0.0f && m.transmission <= 0.0f &&
        m.diffuseTransmission <= 0.0f)
        return ShadeKind::Diffuse;
    // No diffuse lobe, whatever the textures: (1 - metallic)(1 - transmission) is 0.
    const bool metal = m.metallic >= 1.0f && m.metallicRoughnessTexture == WF_NO_TEXTURE;
    const bool clear = m.transmission >= 1.0f && m.transmissionTexture == WF_NO_TEXTURE;
    // Anisotropy stretches even roughness 0 into a lobe with a density (alpha_t = s^2).
    if (m.roughness <= 0.0f && m.anisotropyStrength <= 0.0f && (metal || clear))
        return ShadeKind::Specular;
    return ShadeKind::General;
}

uint32_t shadeKindsPresent(const std::vector<gpu_types::Material>& materials) {
    uint32_t kinds = 0;
    for (const gpu_types::Material& m : materials)
        kinds |= 1u << static_cast<uint32_t>(shadeKind(m));
    return kinds;
}

uint32_t shadeKindsFor(uint32_t present) {
    return std::popcount(present) > 1 ? present : 0u;
}

uint32_t shadeKindsFor(uint32_t present, ShadeSplit split) {
    const bool general = (present & (1u << static_cast<uint32_t>(ShadeKind::General))) != 0;
    if (split == ShadeSplit::Off || (split == ShadeSplit::Auto && general))
        return 0u;
    return shadeKindsFor(present);
}

uint32_t shadeBinOf(uint32_t kinds, ShadeKind kind) {
    const uint32_t below = (1u << static_cast<uint32_t>(kind)) - 1u;
    return static_cast<uint32_t>(std::popcount(kinds & below));
}

uint32_t lightHitBin(uint32_t kinds) {
    for (ShadeKind kind : {ShadeKind::Specular, ShadeKind::Diffuse, ShadeKind::General})
        if (kinds & (1u << static_cast<uint32_t>(kind)))
            return shadeBinOf(kinds, kind);
    return 0; // no bins: one shade pass
}

} // namespace wf
