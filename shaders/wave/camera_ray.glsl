// The camera ray of one pixel sample, shared by the raygen pass and the megakernel.
// Needs bindings.glsl (params), rng.h and (WF_THIN_LENS) sampling.h.
#ifndef WF_CAMERA_RAY_GLSL
#define WF_CAMERA_RAY_GLSL

void cameraRay(uint pixel, uint sampleIndex, out vec3 origin, out vec3 direction) {
    uint x = pixel % params.width;
    uint y = pixel / params.width;
    // Box filter: a uniform point inside the pixel; row 0 is the top of the image.
    vec2 jitter = sample2D(pixel, sampleIndex, WF_DIM_PIXEL, params.seed);
    vec2 ndc = (vec2(x, y) + jitter) / vec2(params.width, params.height) * 2.0 - 1.0;
    if (params.orthoHalfHeight > 0.0) { // orthographic: parallel rays from the view's plane
        origin = params.cameraPosition +
                 params.cameraRight * (ndc.x * params.orthoHalfHeight * params.aspect) -
                 params.cameraUp * (ndc.y * params.orthoHalfHeight);
        direction = params.cameraForward;
        return;
    }
    vec3 d = params.cameraForward +
             params.cameraRight * (ndc.x * params.tanHalfFovY * params.aspect) -
             params.cameraUp * (ndc.y * params.tanHalfFovY);
#if WF_THIN_LENS
    // d has unit length along cameraForward, so d x focusDistance lands on the plane in focus;
    // the ray leaves a point of the lens disc (concentric mapping) towards it.
    vec2 lens = params.lensRadius *
                sampleConcentricDisk(sample2D(pixel, sampleIndex, WF_DIM_LENS, params.seed));
    origin = params.cameraPosition + params.cameraRight * lens.x + params.cameraUp * lens.y;
    direction = normalize(params.cameraPosition + d * params.focusDistance - origin);
#else
    origin = params.cameraPosition;
    direction = normalize(d);
#endif
}

#endif
