// Ray cones in the passes (the rule and its math: ray_cones.h): the camera ray's cone from the
// render parameters. Compiled only with WF_RAY_CONES (textured scenes); needs bindings.glsl.
#ifndef WF_RAY_CONES_GLSL
#define WF_RAY_CONES_GLSL
#if WF_RAY_CONES
#include "surface/ray_cones.h"

// An orthographic camera's cone keeps the pixel's width and does not spread.
vec2 cameraCone() {
    return params.orthoHalfHeight > 0.0 ? vec2(2.0 * params.orthoHalfHeight / float(params.height), 0.0)
                                        : cameraCone(params.tanHalfFovY, params.height);
}

#endif
#endif
