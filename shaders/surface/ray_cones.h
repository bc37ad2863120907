// Ray cones for texture filtering (Akenine-Moeller et al., "Texture Level of Detail Strategies
// for Real-Time Ray Tracing", Ray Tracing Gems 2019, ch. 20; and "Improved Shader and Texture
// Level of Detail Using Ray Cones", JCGT 2021). Each ray carries a cone: its width at the ray's
// origin and its spread angle. The rule:
//   camera ray:  width 0, spread = the angle one pixel subtends at the image centre;
//   at a hit:    width += spread x t (the hit's distance);
//   at a bounce: spread += the sampled lobe's angular width, 2 / sqrt(pi pdf) (the full angle
//                of a cone whose solid angle is 1 / pdf): 0 for Dirac lobes (mirrors, smooth
//                glass), about 4 alpha near a GGX lobe's peak (alpha = roughness^2), 2 rad or
//                more for Lambert; the spread is capped at pi / 2.
//   the level:   lambda = 0.5 log2(texel area / world area) + log2(width / |cos|), clamped to
//                the mip chain (the areas are the hit triangle's, in texels and in the world).
// Surface curvature is not counted (the 2021 paper's beta term), nor a thin lens's aperture.
// Shared by GLSL (WF_RAY_CONES variants) and the CPU tests.
#ifndef WF_RAY_CONES_H
#define WF_RAY_CONES_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

#define WF_MAX_CONE_SPREAD 1.5707963f

// (width at the origin, spread) of a camera ray, for an image `height` pixels high.
WF_INLINE vec2 cameraCone(float tanHalfFovY, uint height) {
    return vec2(0.0f, atan(2.0f * tanHalfFovY / float(height)));
}

WF_INLINE float coneWidthAt(vec2 cone, float t) { return cone.x + cone.y * t; }

// The continuation's cone from the width at the hit and the density the bounce sampled its
// direction with (0: a Dirac lobe).
WF_INLINE vec2 coneAfterBounce(vec2 cone, float widthAtHit, float pdf) {
    float lobe = pdf > 0.0f ? 2.0f * inversesqrt(3.14159265f * pdf) : 0.0f;
    return vec2(widthAtHit, min(cone.y + lobe, WF_MAX_CONE_SPREAD));
}

// The hit's part of lambda, per unit of sqrt(texel area): width / (|cos| sqrt(world area)), with
// `worldArea2` twice the triangle's area. Grazing hits are held at |cos| = 1e-4 so that it stays
// finite (the level is clamped to the chain anyway).
WF_INLINE float coneFootprint(float width, float cosTheta, float worldArea2) {
    return width / (max(abs(cosTheta), 1e-4f) * sqrt(worldArea2));
}

// lambda for a texture whose texels cover `texelArea2` (twice the triangle's area in texels),
// clamped to [0, levels - 1]; NaN (no UV area and no width) gives level 0.
WF_INLINE float coneTextureLod(float footprint, float texelArea2, uint levels) {
    float lod = 0.5f * log2(footprint * footprint * texelArea2);
    return lod > 0.0f ? min(lod, float(levels - 1u)) : 0.0f;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
