// MIS weights of bidirectional path tracing and vertex connection and merging, computed from
// running sums carried along each subpath (Georgiev, Krivanek, Davidovic, Slusallek 2012, and
// Georgiev's report "Implementing Vertex Connection and Merging"): a connection or a merge then
// weighs itself from its two vertices alone, with no walk back along either subpath.
//
// Path x0 (camera) ... xk (light). Strategy (s, t) joins s light vertices to t camera vertices;
// merging at xi joins the camera subpath x0..xi to a light subpath that also reached xi. A
// strategy's weight is (n p)^beta / sum_j (n_j p_j)^beta with p the path's density in area
// measure (solid angle for the "position" of an infinite light) and n its samples per pixel:
// 1, lightPathCount for t = 1 (every light path splats), eta_VCM = pi r^2 lightPathCount for a
// merge. Dirac vertices (specular bounces) are never connected or merged, and their delta pdfs
// cancel between the strategies that remain, so they enter as the finite lobe pdfs given.
//
// For a vertex xi of either subpath, with p->(xj) its own subpath's area density of xj and
// p<-(xj) the other subpath's, let S_i = the sum over every strategy that stops this subpath
// before xi or merges before xi (relative to the one joining xi to the other side), divided by
// p<-(xi)^beta. Then S_i = mergeOverConnect + dVCM + dVC * pRev^beta, pRev being the solid-angle
// pdf at xi towards x(i-1) given the other side's direction, and the carried quantities are
// (already raised to beta, so no weight takes a power of a sum):
//   dVCM: (n / p->(xi))^beta of the strategy joining x(i-1) to xi; 0 when that is impossible.
//   dVC:  S(i-1) * (cos at x(i-1) / (p->(x(i-1) -> xi) solid angle * cos at xi))^beta.
//   dVM:  dVC / eta_VCM^beta: the same sum measured against a merge at xi.
#ifndef WF_VCM_MIS_H
#define WF_VCM_MIS_H

#include "types/glsl_cpp.h"

#ifdef __cplusplus
namespace wf::gpu_types {
using namespace glm;
#endif

// Per-frame constants; makeVcmMisConfig fills them from the render's settings.
struct VcmMisConfig {
    float exponent;         // beta: 1 the balance heuristic, 2 the power heuristic
    float lightPathCount;   // light subpaths traced per frame; each splats onto the image (t = 1)
    float connections;      // 1 when the connection strategies (s = 1, t = 1, s, t >= 2) run
    float merges;           // 1 when merging runs
    float mergeOverConnect; // eta_VCM^beta when merging runs, else 0
    float connectOverMerge; // eta_VCM^-beta when merging runs, else 0
};

// The running quantities of one subpath vertex (definitions above).
struct VcmSubpathMis {
    float dVCM;
    float dVC;
    float dVM;
};

WF_INLINE float vcmPow(float x, float exponent) {
    // The two heuristics in use are exact products; pow() is undefined at 0 in GLSL.
    if (exponent == 1.0f) {
        return x;
    }
    if (exponent == 2.0f) {
        return x * x;
    }
    return pow(x, exponent);
}

WF_INLINE float vcmMis(VcmMisConfig cfg, float x) {
    return vcmPow(x, cfg.exponent);
}

// etaVcm = pi r^2 lightPathCount. Merging needs etaVcm > 0; with useConnections false the
// estimator is photon mapping with MIS against the camera hitting emitters.
WF_INLINE VcmMisConfig makeVcmMisConfig(float exponent, float lightPathCount, float etaVcm,
                                        bool useConnections, bool useMerging) {
    bool merging = useMerging && etaVcm > 0.0f;
    VcmMisConfig cfg;
    cfg.exponent = exponent;
    cfg.lightPathCount = lightPathCount;
    cfg.connections = useConnections ? 1.0f : 0.0f;
    cfg.merges = merging ? 1.0f : 0.0f;
    cfg.mergeOverConnect = merging ? vcmPow(etaVcm, exponent) : 0.0f;
    cfg.connectOverMerge = merging ? vcmPow(1.0f / etaVcm, exponent) : 0.0f;
    return cfg;
}

// cameraPdfW: solid-angle density of the camera ray per pixel, W H cameraDirectionPdf
// (camera_importance.h), the density one pixel's camera sample has against the lightPathCount
// light subpaths that splat into it with cameraSplatScale = W H / lightPathCount. (The whole
// image's cameraDirectionPdf alone weighs the same strategies with another n: unbiased, but far
// from the heuristic.) dVC = 0: no light subpath can hit a pinhole.
WF_INLINE VcmSubpathMis vcmStartCamera(VcmMisConfig cfg, float cameraPdfW) {
    VcmSubpathMis v;
    v.dVCM = cfg.connections * vcmMis(cfg, cfg.lightPathCount / cameraPdfW);
    v.dVC = 0.0f;
    v.dVM = 0.0f;
    return v;
}

// directPdfA: next-event estimation's density of this emitter point (light pick times position
// pdf; for an infinite light, the solid-angle pdf of the direction). emissionPdfW: the emitted
// ray's density (pick times position pdf times direction pdf; for an infinite light, direction
// pdf times the pdf on the disk the rays start from). cosAtLight is unused for infinite lights.
WF_INLINE VcmSubpathMis vcmStartLight(VcmMisConfig cfg, float directPdfA, float emissionPdfW,
                                      float cosAtLight, bool finiteLight, bool diracLight) {
    VcmSubpathMis v;
    // Next-event estimation's share, against emitting; NEE is a connection.
    v.dVCM = cfg.connections * vcmMis(cfg, directPdfA / emissionPdfW);
    // The camera hitting the emitter; the disk of an infinite light is already perpendicular to
    // its rays, so no cosine there, and nothing can hit a point or directional light.
    float usedCos = finiteLight ? cosAtLight : 1.0f;
    v.dVC = diracLight ? 0.0f : vcmMis(cfg, usedCos / emissionPdfW);
    v.dVM = v.dVC * cfg.connectOverMerge;
    return v;
}

// The ray from the previous vertex reached the next one: the solid-angle densities turn into
// area densities there. Pass distSq = 1 on the segment leaving an infinite light, whose disk
// pdf is already per unit area.
WF_INLINE void vcmOnHit(VcmMisConfig cfg, WF_INOUT(VcmSubpathMis) v, float distSq,
                        float cosAtHit) {
    float invCos = 1.0f / vcmMis(cfg, abs(cosAtHit));
    v.dVCM *= vcmMis(cfg, distSq) * invCos;
    v.dVC *= invCos;
    v.dVM *= invCos;
}

// The subpath scattered at its vertex: pdfW samples the new direction (cosOut to the normal),
// revPdfW the way back given the new direction. A Dirac bounce cannot end a subpath, so the
// strategies joining or merging here drop out and only the earlier ones carry through it.
WF_INLINE void vcmOnScatter(VcmMisConfig cfg, WF_INOUT(VcmSubpathMis) v, float cosOut,
                            float pdfW, float revPdfW, bool dirac) {
    float scale = vcmMis(cfg, abs(cosOut) / pdfW);
    float rev = vcmMis(cfg, revPdfW);
    if (dirac) {
        v.dVCM = 0.0f;
        v.dVC *= scale * rev;
        v.dVM *= scale * rev;
        return;
    }
    float dVC = scale * (v.dVC * rev + v.dVCM + cfg.mergeOverConnect);
    float dVM = scale * (v.dVM * rev + v.dVCM * cfg.connectOverMerge + cfg.merges);
    v.dVC = dVC;
    v.dVM = dVM;
    v.dVCM = cfg.connections * vcmMis(cfg, 1.0f / pdfW);
}

// S_i of the definitions: this side's other strategies over p<-(xi)^beta.
WF_INLINE float vcmSideSum(VcmMisConfig cfg, VcmSubpathMis v, float revPdfW) {
    return cfg.mergeOverConnect + v.dVCM + v.dVC * vcmMis(cfg, revPdfW);
}

// The camera subpath hit an emitter (s = 0): pdfs as in vcmStartLight for the point hit. Call
// with the camera state after vcmOnHit for a finite light, before it (none) for an infinite
// one. Not for the first camera vertex: a camera ray that sees an emitter directly has weight
// 1, because this strategy set leaves out splatting emitter points onto the image, but this
// function counts that splat (camera.dVCM is nonzero there) and would darken the direct view;
// the caller uses 1 (tests/unit/test_bidir_reference.cpp).
WF_INLINE float vcmWeightEmitterHit(VcmMisConfig cfg, VcmSubpathMis camera, float directPdfA,
                                    float emissionPdfW) {
    float others = vcmMis(cfg, directPdfA) * camera.dVCM + vcmMis(cfg, emissionPdfW) * camera.dVC;
    return 1.0f / (1.0f + others);
}

// Next-event estimation (s = 1) from a camera vertex. neePdfW: solid-angle density at the vertex
// of the sampled emitter point, pick included. bsdfPdfW: the vertex's pdf of scattering towards
// it (0 for Dirac lights, which no bounce can hit); bsdfRevPdfW: back along the camera subpath.
// cosAtLight: 1 for infinite lights; cosToLight: at the camera vertex.
WF_INLINE float vcmWeightNee(VcmMisConfig cfg, VcmSubpathMis camera, float neePdfW,
                             float bsdfPdfW, float bsdfRevPdfW, float emissionPdfW,
                             float cosAtLight, float cosToLight) {
    float wLight = vcmMis(cfg, bsdfPdfW / neePdfW);
    // The light subpath's area density of the camera vertex, times emission over NEE position
    // pdfs in case the two sample the light differently.
    float lightToCameraPdfA = emissionPdfW * abs(cosToLight) / (neePdfW * abs(cosAtLight));
    float wCamera = vcmMis(cfg, lightToCameraPdfA) * vcmSideSum(cfg, camera, bsdfRevPdfW);
    return 1.0f / (wLight + 1.0f + wCamera);
}

// A light vertex connected to the camera (t = 1). cameraPdfA: the camera's area density of this
// vertex (vcmStartCamera's density times cos at the vertex over distance^2). bsdfRevPdfW: the
// vertex's pdf of scattering back along the light subpath given the direction to the camera.
WF_INLINE float vcmWeightCameraConnect(VcmMisConfig cfg, VcmSubpathMis light, float cameraPdfA,
                                       float bsdfRevPdfW) {
    float wLight = vcmMis(cfg, cameraPdfA / cfg.lightPathCount) *
                   vcmSideSum(cfg, light, bsdfRevPdfW);
    return 1.0f / (wLight + 1.0f);
}

// A connection of a camera vertex and a light vertex (s, t >= 2). cameraPdfW: the camera
// vertex's pdf of scattering to the light vertex, cameraRevPdfW back along its subpath given
// that direction; lightPdfW and lightRevPdfW likewise at the light vertex. Cosines at each end
// of the connecting segment, distSq its squared length.
WF_INLINE float vcmWeightConnect(VcmMisConfig cfg, VcmSubpathMis camera, VcmSubpathMis light,
                                 float cameraPdfW, float cameraRevPdfW, float lightPdfW,
                                 float lightRevPdfW, float cosAtCamera, float cosAtLight,
                                 float distSq) {
    float cameraToLightPdfA = cameraPdfW * abs(cosAtLight) / distSq;
    float lightToCameraPdfA = lightPdfW * abs(cosAtCamera) / distSq;
    float wLight = vcmMis(cfg, cameraToLightPdfA) * vcmSideSum(cfg, light, lightRevPdfW);
    float wCamera = vcmMis(cfg, lightToCameraPdfA) * vcmSideSum(cfg, camera, cameraRevPdfW);
    return 1.0f / (wLight + 1.0f + wCamera);
}

// A merge of a camera vertex with a light vertex found within the radius. cameraPdfW: the
// camera vertex's pdf of scattering towards the light vertex's predecessor (the reversed photon
// direction); cameraRevPdfW: back along the camera subpath given that direction.
WF_INLINE float vcmWeightMerge(VcmMisConfig cfg, VcmSubpathMis camera, VcmSubpathMis light,
                               float cameraPdfW, float cameraRevPdfW) {
    float wLight = light.dVCM * cfg.connectOverMerge + light.dVM * vcmMis(cfg, cameraPdfW);
    float wCamera = camera.dVCM * cfg.connectOverMerge + camera.dVM * vcmMis(cfg, cameraRevPdfW);
    return 1.0f / (wLight + 1.0f + wCamera);
}

// The most any merge at a camera vertex can weigh, known before its query: the light side's
// terms and the reverse pdf's are not negative, so the weight is at most 1 / (1 + the camera
// subpath's connection term). vcm_merge.glsl plays Russian roulette on queries it bounds low.
WF_INLINE float vcmMergeWeightBound(VcmMisConfig cfg, VcmSubpathMis camera) {
    return 1.0f / (1.0f + camera.dVCM * cfg.connectOverMerge);
}

#ifdef __cplusplus
} // namespace wf::gpu_types
#endif

#endif
