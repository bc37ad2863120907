// The camera as an end of a light path (issue 46): its importance We, the densities of the
// rays it issues, and the pixel a light vertex is seen in, for the pinhole and the thin lens of
// wave/camera_ray.glsl. Pure math on a camera of its own (not RenderParams), so the CPU tests
// in tests/unit/test_camera_importance.cpp check exactly what a light or BDPT pass would run.
//
// Normalisation (Veach 1997 5.4, pbrt-v4 PerspectiveCamera::We): We is the importance of the
// whole image, integral of We(p, w) cos(theta) dw dA(p) over lens and directions = 1, with
// A = (2 tanHalfFovY aspect)(2 tanHalfFovY) the image plane's area at distance 1. The path
// tracer's pixel j holds the box-filtered mean, integral over the pixel of L dx (dx = 1 for a
// pixel, A / (W H) of that plane; dw = cos^3(theta) dA on it; the lens averaged too), which is
// W H times the measurement with We restricted to pixel j. So a light tracer that traces N
// light paths per sample index, splatting into a film that divides by the samples per pixel,
// adds to the pixel of cameraRasterOfPoint
//   (W H / N) We(p, w) x (the rest of the path's contribution) / (its pdfs),
// W H / N being cameraSplatScale: 1 when each sample index traces one light path per pixel
// (pbrt-v4's light tracer). tests/unit/test_camera_importance.cpp checks this on a render.
#ifndef WF_CAMERA_IMPORTANCE_H
#define WF_CAMERA_IMPORTANCE_H

#include "types/glsl_cpp.h"
#include "sampling/sampling.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// right, up and forward orthonormal as RenderParams holds them; lensRadius 0 is a pinhole.
struct CameraGeometry {
    vec3 position;
    float tanHalfFovY;
    vec3 forward;
    float aspect; // width / height
    vec3 right;
    float lensRadius;
    vec3 up;
    float focusDistance; // along forward, to the plane in focus (thin lens only)
    uint width;
    uint height;
    float orthoHalfHeight; // > 0: orthographic, which has no finite importance to connect to
};

// Light and BDPT vertices connect to the camera only through a lens that rays can reach: an
// orthographic camera's rays are parallel (a Dirac in direction for every point of the view
// plane), so no connection can hit it, and issue 46 refuses it for light, bdpt and vcm.
WF_INLINE bool cameraConnectable(CameraGeometry camera) {
    return camera.orthoHalfHeight <= 0.0f && camera.tanHalfFovY > 0.0f;
}

WF_INLINE float cameraImageArea(CameraGeometry camera) {
    return 4.0f * camera.tanHalfFovY * camera.tanHalfFovY * camera.aspect;
}

// The lens point's area density: 1 for the pinhole, whose point is a Dirac that the
// measurement integrates away, uniform over the disc for the thin lens.
WF_INLINE float cameraLensPdf(CameraGeometry camera) {
    return camera.lensRadius > 0.0f ? 1.0f / (WF_PI * camera.lensRadius * camera.lensRadius)
                                    : 1.0f;
}

// The lens point of camera_ray.glsl's sample u (dimensions WF_DIM_LENS): its concentric disc.
WF_INLINE vec3 cameraLensPoint(CameraGeometry camera, vec2 u) {
    if (camera.lensRadius <= 0.0f) {
        return camera.position;
    }
    vec2 lens = camera.lensRadius * sampleConcentricDisk(u);
    return camera.position + camera.right * lens.x + camera.up * lens.y;
}

// The raster position (continuous pixels, row 0 at the top, as camera_ray.glsl maps ndc) of a
// direction d from the camera's centre; false behind the camera or off the image.
WF_INLINE bool cameraRasterOfCentreDirection(CameraGeometry camera, vec3 d, WF_OUT(vec2) raster) {
    raster = vec2(-1.0f);
    float z = dot(d, camera.forward);
    if (!(z > 0.0f)) {
        return false;
    }
    // Divide by z instead of normalising: camera_ray.glsl's d has unit length along forward.
    vec2 ndc = vec2(dot(d, camera.right) / (z * camera.tanHalfFovY * camera.aspect),
                    -dot(d, camera.up) / (z * camera.tanHalfFovY));
    raster = (ndc + 1.0f) * 0.5f * vec2(float(camera.width), float(camera.height));
    return raster.x >= 0.0f && raster.y >= 0.0f && raster.x < float(camera.width) &&
           raster.y < float(camera.height);
}

// The raster position of the ray leaving lensPoint along w. A thin-lens ray is the one that
// camera_ray.glsl aims through the point X in focus, so X (where the ray meets the plane at
// focusDistance) seen from the centre gives the pixel. lensPoint lies on the lens plane.
WF_INLINE bool cameraRasterOfRay(CameraGeometry camera, vec3 lensPoint, vec3 w,
                                 WF_OUT(vec2) raster) {
    raster = vec2(-1.0f);
    if (camera.lensRadius <= 0.0f) {
        return cameraRasterOfCentreDirection(camera, w, raster);
    }
    float z = dot(w, camera.forward);
    if (!(z > 0.0f)) {
        return false;
    }
    vec3 inFocus = lensPoint + w * (camera.focusDistance / z);
    return cameraRasterOfCentreDirection(camera, inFocus - camera.position, raster);
}

// The unit direction from lensPoint towards a world point (a light vertex), the raster position
// it is splatted to and the squared distance for the geometry term; false when the point is
// behind the lens plane or off the image.
WF_INLINE bool cameraRasterOfPoint(CameraGeometry camera, vec3 lensPoint, vec3 point,
                                   WF_OUT(vec3) w, WF_OUT(vec2) raster, WF_OUT(float) dist2) {
    vec3 d = point - lensPoint;
    dist2 = dot(d, d);
    if (!(dist2 > 0.0f)) { // on the lens: no direction, and w = 0 has no importance either
        w = vec3(0.0f);
        raster = vec2(-1.0f);
        return false;
    }
    w = d / sqrt(dist2);
    return cameraRasterOfRay(camera, lensPoint, w, raster);
}

// We(lensPoint, w) for a unit w: 1 / (A lensArea cos^4 theta) on the image, 0 off it (theta
// from forward). cos^4: one cos^3 turns the image plane's area into solid angle, one more
// because We is per projected solid angle. Whole-image normalisation: see the top of the file.
WF_INLINE float cameraImportance(CameraGeometry camera, vec3 lensPoint, vec3 w) {
    vec2 raster;
    if (!cameraRasterOfRay(camera, lensPoint, w, raster)) {
        return 0.0f;
    }
    float cosTheta = dot(w, camera.forward);
    float cos2 = cosTheta * cosTheta;
    return cameraLensPdf(camera) / (cameraImageArea(camera) * cos2 * cos2);
}

// Solid-angle density of the ray direction camera_ray.glsl draws from lensPoint (a uniform
// raster point, so a uniform point on the plane in focus): 1 / (A cos^3 theta) on the image.
WF_INLINE float cameraDirectionPdf(CameraGeometry camera, vec3 lensPoint, vec3 w) {
    vec2 raster;
    if (!cameraRasterOfRay(camera, lensPoint, w, raster)) {
        return 0.0f;
    }
    float cosTheta = dot(w, camera.forward);
    return 1.0f / (cameraImageArea(camera) * cosTheta * cosTheta * cosTheta);
}

// The factor a light tracer's splat carries (see the top of the file): W H / (light paths per
// sample index), with the film dividing the splats by the samples per pixel.
WF_INLINE float cameraSplatScale(CameraGeometry camera, float lightPathsPerSampleIndex) {
    return float(camera.width) * float(camera.height) / lightPathsPerSampleIndex;
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
