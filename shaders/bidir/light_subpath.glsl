// A light subpath in the wavefront (--integrator light, issue 46): its sample dimensions, its
// first ray (light_emission.h from a light chosen by the emitter table's pmf) and its vertices'
// connections to the camera (camera_importance.h), shared by light_raygen.comp and
// light_shade.comp. Includers provide bindings, geometry, rng, sampling, light_sampling,
// surface and lights (lights.glsl needs WF_HAS_EMITTERS).
//
// Sample dimensions (docs/bidirectional.md): after the camera path's maxDepth bounces, so that
// a BDPT sample drives both subpaths from one index without sharing a number.
//   bounce slot maxDepth:          the emission, offsets WF_LIGHT_DIM_* below;
//   bounce slot maxDepth + 1 + d:  light vertex d (the vertex its ray d + 1 found): the BSDF
//                                  sample as a camera vertex takes it (WF_DIM_BSDF_LOBE,
//                                  WF_DIM_BSDF, WF_DIM_ROULETTE) and the lens point of its
//                                  camera connection at WF_DIM_LIGHT_POINT.
#ifndef WF_LIGHT_SUBPATH_GLSL
#define WF_LIGHT_SUBPATH_GLSL
#include "bidir/light_emission.h"
#include "bidir/scene_camera.glsl"
#include "bidir/light_share.glsl"

#define WF_LIGHT_DIM_CHOICE 0u    // 1D: the emitter
#define WF_LIGHT_DIM_POINT 1u     // 2D: the point on it (or on the scene's disk)
#define WF_LIGHT_DIM_DIRECTION 3u // 2D: the direction of emission
#define WF_LIGHT_DIM_EXTRA 5u     // 1D: the environment's texel

float lightEmissionSample1D(uint pixel, uint sampleIndex, uint offset) {
    return sample1D(pixel, sampleIndex, bounceDimension(params.maxDepth, offset), params.seed);
}

vec2 lightEmissionSample2D(uint pixel, uint sampleIndex, uint offset) {
    return sample2D(pixel, sampleIndex, bounceDimension(params.maxDepth, offset), params.seed);
}

float lightVertexSample1D(uint pixel, uint sampleIndex, uint depth, uint offset) {
    return sample1D(pixel, sampleIndex, bounceDimension(params.maxDepth + 1u + depth, offset),
                    params.seed);
}

vec2 lightVertexSample2D(uint pixel, uint sampleIndex, uint depth, uint offset) {
    return sample2D(pixel, sampleIndex, bounceDimension(params.maxDepth + 1u + depth, offset),
                    params.seed);
}

// The first ray of a light subpath, and what BDPT's MIS needs of its start.
struct EmittedRay {
    vec3 origin;        // off the light's surface
    vec3 direction;     // the way light travels
    vec3 beta;          // emitted cos / (pick pdfA pdfW)
    uint emitter;       // the emitter-table entry it left
    float emissionPdfW; // pick pdfA pdfW (infinite lights: the scene disk's pdfA)
    float cosAtLight;   // at the light point; 1 for points and infinite lights
};

// The first ray of the light subpath of (pixel, sampleIndex). False when it carries nothing
// (no light, a grazing direction, a dark texel).
bool emitLightRay(uint pixel, uint sampleIndex, out EmittedRay ray) {
    ray.origin = vec3(0.0);
    ray.direction = vec3(0.0, 0.0, 1.0);
    ray.beta = vec3(0.0);
    ray.emissionPdfW = 0.0;
    ray.cosAtLight = 1.0;
    uint emitter = chooseEmitter(lightEmissionSample1D(pixel, sampleIndex, WF_LIGHT_DIM_CHOICE));
    ray.emitter = emitter;
    float pmf = emitterAt(emitter).pmf;
    if (!(pmf > 0.0))
        return false;
    vec2 uPoint = lightEmissionSample2D(pixel, sampleIndex, WF_LIGHT_DIM_POINT);
    vec2 uDirection = lightEmissionSample2D(pixel, sampleIndex, WF_LIGHT_DIM_DIRECTION);
    uint source = emitterAt(emitter).source;
    uint index = source & WF_EMITTER_INDEX_MASK;
    uint kind = source & WF_EMITTER_KIND_MASK;
    EmissionSample e;
    e.pdfA = 0.0;
    e.pdfW = 0.0;
    vec3 originError = vec3(0.0);
    bool surfacePoint = false; // a triangle's or a sphere's, with a cosine there
#if WF_HAS_TRIANGLE_EMITTERS
    if (kind == WF_EMITTER_TRIANGLE) {
        Triangle tri = triangleAt(index);
        Material material = materialAt(tri.material);
        vec2 b = sampleUniformTriangle(uPoint); // emitTriangle's point, for textured emission
        e = emitTriangle(tri.p0, tri.p1, tri.p2, surfaceEmission(index, material, b.x, b.y),
                         (material.flags & WF_MATERIAL_DOUBLE_SIDED) != 0u, uPoint, uDirection);
        originError = triangleSpawnError(tri.p0, tri.p1, tri.p2, b.x, b.y);
        surfacePoint = true;
    }
#endif
#if WF_HAS_ENVIRONMENT
    if (kind == WF_EMITTER_ENVIRONMENT) {
        // sampleEnvironment's density holds the choice: take it out, as pmf divides below.
        LightSample s = sampleEnvironment(
            lightEmissionSample1D(pixel, sampleIndex, WF_LIGHT_DIM_EXTRA), uDirection,
            params.sceneCenter);
        e = emitEnvironment(s.direction, s.radiance, s.pdf / pmf, params.sceneCenter,
                            params.sceneRadius, uPoint);
    }
#endif
#if WF_HAS_LIGHTS
    if (kind == WF_EMITTER_LIGHT) {
        PunctualLight light = lightAt(index);
        if (light.type == WF_LIGHT_SPHERE) {
#if WF_HAS_SPHERE_LIGHTS
            e = emitSphere(light.position, light.radius, sphereRadiance(light), uPoint,
                           uDirection);
            originError = spherePointError(light);
            surfacePoint = true;
#endif
        } else if (light.type == WF_LIGHT_POINT) {
            e = emitPoint(light.position, light.intensity, uDirection);
        } else if (light.type == WF_LIGHT_SPOT) {
            e = emitSpot(light.position, light.direction, light.intensity, light.cosInner,
                         light.cosOuter, uDirection);
        } else {
            e = emitDirectional(light.direction, light.intensity, params.sceneCenter,
                                params.sceneRadius, uPoint);
        }
    }
#endif
    if (!(e.pdfA > 0.0) || !(e.pdfW > 0.0))
        return false;
    ray.beta = emissionThroughput(e) / pmf;
    ray.direction = e.direction;
    ray.emissionPdfW = pmf * e.pdfA * e.pdfW;
    ray.cosAtLight = surfacePoint ? abs(dot(e.normal, e.direction)) : 1.0;
    // Points and the scene's disk lie on no surface; the others leave theirs by the ray offset.
    ray.origin = any(greaterThan(originError, vec3(0.0)))
                     ? offsetRayOrigin(e.origin, originError, e.normal, e.direction)
                     : e.origin;
    return any(greaterThan(ray.beta, vec3(0.0)));
}


// What a surface point p sends to the camera for importance-weighted value `valueToCamera`
// (the light subpath's throughput times the BSDF towards the lens and its cosine, both
// evaluated by the caller once the direction is known): the lens point, the pixel, and the
// splat, We cos(camera) / (dist^2 lens pdf) x W H / (light paths per sample index); one light
// path per pixel and sample index makes the last factor 1. False off the image or behind it.
struct CameraConnection {
    vec3 lensPoint;
    vec3 toCamera; // unit, from p towards the lens point
    uint pixel;
    float importance;   // the splat's factor for valueToCamera
    float dist2;        // from p to the lens point
    float directionPdf; // the camera's density of the ray towards p (cameraDirectionPdf)
};

bool connectToCamera(vec3 p, vec2 uLens, out CameraConnection c) {
    CameraGeometry camera = sceneCamera();
    c.lensPoint = cameraLensPoint(camera, uLens);
    c.toCamera = vec3(0.0, 0.0, 1.0);
    c.pixel = 0u;
    c.importance = 0.0;
    c.dist2 = 0.0;
    c.directionPdf = 0.0;
    vec3 w;
    vec2 raster;
    float dist2;
    if (!cameraRasterOfPoint(camera, c.lensPoint, p, w, raster, dist2))
        return false;
    uvec2 xy = min(uvec2(raster), uvec2(params.width - 1u, params.height - 1u));
    c.pixel = xy.y * params.width + xy.x;
    c.toCamera = -w;
    c.dist2 = dist2;
    c.directionPdf = cameraDirectionPdf(camera, c.lensPoint, w);
    float cosCamera = dot(w, camera.forward);
    c.importance = cameraImportance(camera, c.lensPoint, w) * cosCamera /
                   (dist2 * cameraLensPdf(camera));
    return c.importance > 0.0;
}

#endif
