// The mean of a triangle's emissive texture over its UV footprint, for the light table's power
// estimate (the emission factor alone overweights a mostly dark texture, and a weight of zero
// would stop NEE from ever choosing a triangle that does shine somewhere).
#pragma once
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/surface_data.h"

namespace wf {

// Mean linear RGB of texture reference `ref` over triangle `triangle` (stratified barycentric
// samples, one per texel of the footprint up to 1,024, nearest texels, the texture transform
// and wrap modes applied), each channel at least 1/1024 so that no part that shines is lost;
// 1 (the factor alone) where `ref` names no texture of `surface`.
glm::vec3 meanEmissiveTexture(const SurfaceData& surface, uint32_t ref, uint32_t triangle);

} // namespace wf
