// Ray cones in the passes (the rule and its math: ray_cones.h): the camera ray's cone from the
// render parameters. Compiled only with WF_RAY_CONES (textured scenes); needs bindings.glsl.
#ifndef WF_RAY_CONES_GLSL
#define WF_RAY_CONES_GLSL
#if WF_RAY_CONES
#include "surface/ray_cones.h"

vec2 cameraCone() {
    // An orthographic camera's cone keeps a pixel's width and does not spread.
    return params.orthoHalfHeight > 0.0
               ? vec2(2.0 * params.orthoHalfHeight / float(params.height), 0.0)
               : cameraCone(params.tanHalfFovY, params.height);
}

#endif
#endif
