// The camera ray of one pixel sample, shared by the raygen pass and the megakernel. With
// WF_MOTION it also draws the path's time (wfRayTime, motion.glsl), a box shutter, and a moving
// camera looks from where it is then.
// Needs bindings.glsl (params), rng.h and (WF_THIN_LENS) sampling.h.
#ifndef WF_CAMERA_RAY_GLSL
#define WF_CAMERA_RAY_GLSL

void cameraRay(uint pixel, uint sampleIndex, out vec3 origin, out vec3 direction) {
    uint x = pixel % params.width;
    uint y = pixel / params.width;
    // Box filter: a uniform point inside the pixel; row 0 is the top of the image.
    vec2 jitter = sample2D(pixel, sampleIndex, WF_DIM_PIXEL, params.seed);
    vec2 ndc = (vec2(x, y) + jitter) / vec2(params.width, params.height) * 2.0 - 1.0;
    vec3 cameraPosition = params.cameraPosition;
    vec3 cameraForward = params.cameraForward;
    vec3 cameraUp = params.cameraUp;
    vec3 cameraRight = params.cameraRight;
#if WF_MOTION
    wfRayTime = sample1D(pixel, sampleIndex, WF_DIM_TIME, params.seed);
    if (params.cameraMotionKeys != 0u)
        movingCameraFrame(cameraPosition, cameraForward, cameraRight, cameraUp);
#endif
    if (params.orthoHalfHeight > 0.0) { // orthographic: parallel rays from the view's plane
        origin = cameraPosition +
                 cameraRight * (ndc.x * params.orthoHalfHeight * params.aspect) -
                 cameraUp * (ndc.y * params.orthoHalfHeight);
        direction = cameraForward;
        return;
    }
    vec3 d = cameraForward +
             cameraRight * (ndc.x * params.tanHalfFovY * params.aspect) -
             cameraUp * (ndc.y * params.tanHalfFovY);
#if WF_THIN_LENS
    // d has unit length along cameraForward, so d x focusDistance lands on the plane in focus;
    // the ray leaves a point of the lens disc (concentric mapping) towards it.
    vec2 lens = params.lensRadius *
                sampleConcentricDisk(sample2D(pixel, sampleIndex, WF_DIM_LENS, params.seed));
    origin = cameraPosition + cameraRight * lens.x + cameraUp * lens.y;
    direction = normalize(cameraPosition + d * params.focusDistance - origin);
#else
    origin = cameraPosition;
    direction = normalize(d);
#endif
}

#endif
