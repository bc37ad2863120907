// BDPT's connections (s, t >= 2): a camera vertex joined to a kept vertex of its path slot's
// light subpath (bdpt_state.glsl) by one shadow ray, weighed among every strategy that makes
// the path (vcm_mis.h). Included by wave/path_vertex.glsl, which fills a BdptCameraVertex at
// each camera vertex, and called by shade.comp once per light bounce in uniform control flow
// (its appends). Needs bsdf.h or bsdf_layers.h (WF_BSDF_LAYERS), surface.glsl,
// wave/shading_frame.glsl, adjoint_bsdf.h.
#ifndef WF_BDPT_CONNECT_GLSL
#define WF_BDPT_CONNECT_GLSL
#include "bidir/adjoint_bsdf.h"

// What a camera vertex's connections need of it, kept before it scatters.
struct BdptCameraVertex {
    bool connectable;   // a surface with a non-Dirac BSDF
    vec3 p;
    vec3 pError;
    vec3 ng;
    vec3 outside;       // the geometric normal on the side the BSDF's +z is
    vec3 tangent;       // the shading frame, +z = n
    vec3 bitangent;
    vec3 n;
    vec3 woLocal;       // towards the previous camera vertex
    vec3 beta;          // the camera subpath's throughput at the vertex
    VcmSubpathMis mis;  // after vcmOnHit here
    uint sampleIndex;   // its MIS configuration's (and with WF_VCM, its merging radius's)
    uint pixel;         // with sampleIndex, where its random numbers come from
    BsdfParams bsdf;
#if WF_BSDF_LAYERS
    BsdfLayers layers;
#endif
};

vec3 bdptEval(BsdfParams bsdf,
#if WF_BSDF_LAYERS
              BsdfLayers layers,
#endif
              vec3 wo, vec3 wi) {
#if WF_BSDF_LAYERS
    return layeredEval(bsdf, layers, wo, wi);
#else
    return bsdfEval(bsdf, wo, wi);
#endif
}

float bdptPdf(BsdfParams bsdf,
#if WF_BSDF_LAYERS
              BsdfLayers layers,
#endif
              vec3 wo, vec3 wi) {
#if WF_BSDF_LAYERS
    return layeredPdf(bsdf, layers, wo, wi);
#else
    return bsdfPdf(bsdf, wo, wi);
#endif
}

#if WF_BSDF_LAYERS
#define WF_BDPT_LOBES(bsdf, layers) bsdf, layers
#else
#define WF_BDPT_LOBES(bsdf, layers) bsdf
#endif

// Camera vertex c at camera bounce `depth` joined to light bounce d of the light subpath in
// path slot `lightPath` (the one its pixel shares, bidir/light_share.glsl): the segment to
// test (offset off both surfaces) and the weighted value to add to the path's light film entry
// when it is unoccluded. False when there is nothing to connect
// (no kept vertex, a Dirac one, a path over the maximum depth, a zero BSDF).
bool bdptConnect(BdptCameraVertex c, uint lightPath, uint depth, uint d, out vec3 origin,
                 out vec3 segment, out vec3 value) {
    origin = vec3(0.0);
    segment = vec3(0.0);
    value = vec3(0.0);
    if (!c.connectable || d >= lightDepths[lightPath] || depth + d + 3u > params.maxDepth)
        return false;
    uint slot = d * params.pathCapacity + lightPath;
    vec4 lightThroughput = lightVertexThroughputs[slot];
    if (all(equal(lightThroughput.rgb, vec3(0.0))))
        return false;
    uvec4 hit = lightVertexHits[slot];
    vec4 lightDirection = lightVertexDirections[slot];
    vec3 toLight = lightDirection.xyz;
    SurfaceHit s = loadSurface(hit.x, hit.w, uintBitsToFloat(hit.y), uintBitsToFloat(hit.z),
                               toLight, 0.0);
    vec3 toVertex = s.p - c.p;
    float dist2 = dot(toVertex, toVertex);
    if (!(dist2 > 0.0))
        return false;
    vec3 w = toVertex * inversesqrt(dist2); // from the camera vertex to the light vertex
    BsdfParams lightBsdf = bsdfAt(s);
#if WF_BSDF_LAYERS
    BsdfLayers lightLayers = layersAt(s);
#endif
    // The light vertex's frame as light_shade.comp built it (shading_frame.glsl).
    ShadingFrame lightFrame = shadingFrameAt(s);
    vec3 toLightLocal = toShadingFrame(lightFrame, toLight);
#if WF_BSDF_LAYERS && WF_HAS_CLEARCOAT && WF_HAS_CLEARCOAT_NORMAL_MAPS
    placeCoatNormal(lightLayers, s, lightFrame);
#endif
    vec3 toCameraLocal = toShadingFrame(lightFrame, -w);
    vec3 wCamera = vec3(dot(w, c.tangent), dot(w, c.bitangent), dot(w, c.n));

    // Both BSDFs in the radiance order (wo towards the camera): the camera's as the path
    // tracer's NEE takes it, the light's as light_shade's camera connection does, with the
    // shading-normal correction that makes it f_s |cos| against the geometric normal.
    vec3 cameraF = bdptEval(WF_BDPT_LOBES(c.bsdf, c.layers), c.woLocal, wCamera);
    vec3 lightF = bdptEval(WF_BDPT_LOBES(lightBsdf, lightLayers), toCameraLocal, toLightLocal);
    value = c.beta * cameraF * lightF * lightThroughput.rgb *
            (abs(wCamera.z) * abs(toCameraLocal.z) *
             adjointShadingFactor(s.ns, s.ng, toLight, -w) / dist2);

    VcmSubpathMis lightMis;
    lightMis.dVCM = lightDirection.w;
    lightMis.dVC = lightThroughput.w;
    lightMis.dVM = 0.0; // the connection's weight reads dVCM and dVC only
    value *= vcmWeightConnect(
        bdptMisConfig(c.sampleIndex), c.mis, lightMis,
        bdptPdf(WF_BDPT_LOBES(c.bsdf, c.layers), c.woLocal, wCamera),
        bdptPdf(WF_BDPT_LOBES(c.bsdf, c.layers), wCamera, c.woLocal),
        bdptPdf(WF_BDPT_LOBES(lightBsdf, lightLayers), toLightLocal, toCameraLocal),
        bdptPdf(WF_BDPT_LOBES(lightBsdf, lightLayers), toCameraLocal, toLightLocal),
        abs(dot(w, c.ng)), abs(dot(w, s.ng)), dist2);
    value = clampContribution(value);
    origin = offsetRayOrigin(c.p, c.pError, c.outside, w);
    segment = offsetRayOrigin(s.p, s.pError, lightFrame.outside, -w) - origin;
    return any(greaterThan(value, vec3(0.0))) || any(isnan(value));
}

#if WF_VCM
#include "bidir/vcm_merge.glsl"
#endif

#endif
