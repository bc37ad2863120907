// One vertex of a path: what the ray found (emission, MIS-weighted against light sampling), a
// next-event connection to a light, and the BSDF-sampled continuation with Russian roulette.
// The wavefront's shade pass and the megakernel baseline both call shadePathVertex, so the two
// trace the same paths. Includers provide bindings, geometry, rng, sampling, light_sampling,
// bsdf, lights and surface.
// Estimator: WF_LIGHT_SAMPLING 0 = BSDF sampling only, 1 = NEE only, 2 = MIS (power heuristic).
// WF_GUIDING (includers add guiding/guide_bindings.glsl and guide_path.glsl first): at vertices
// with a non-delta BSDF, directions come from a one-sample mixture of the BSDF's sampling
// (share guide.bsdfFraction) and the path guide's quadtree, and the mixture's pdf is what MIS
// weighs against next-event estimation on both sides.
#include "surface/ray_cones.glsl"
// Scenes with a clear coat or sheen shade with bsdf_layers.h's layered BSDF instead of bsdf.h's,
// except in the shade passes of kinds that hold no layered material (WF_BSDF_NO_LAYERS).
#ifndef WF_BSDF_NO_LAYERS
#define WF_BSDF_NO_LAYERS 0
#endif
#if (WF_HAS_CLEARCOAT || WF_HAS_SHEEN) && !WF_BSDF_NO_LAYERS
#define WF_BSDF_LAYERS 1
#include "bsdf/bsdf_layers.h"
#else
#define WF_BSDF_LAYERS 0
#endif
#if WF_HAS_DISPERSION
#include "bsdf/dispersion.h"
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
// --integrator bdpt: every emission, NEE and connection weighed among all strategies.
#include "bidir/bdpt_state.glsl"
#endif

struct PathVertex {
    // In: where the path is.
    uint pixel;
    uint sampleIndex;
    uint depth;        // bounce index: this ray is path segment depth + 1
#if WF_GUIDING || WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    uint path;         // where its training records (bdpt: light vertices) live
#endif
    uvec4 hit;         // from intersectClosest
    // In and out: the ray, and after shading the continuation ray.
    vec3 origin;
    vec3 direction;
    float previousPdf; // BSDF density of `direction` (0: camera ray or a Dirac bounce)
    float previousNormal; // encodeReceiverNormal at the vertex it left (light tree MIS; 0: none)
    vec3 beta;         // throughput
    float etaScale;    // product of eta^2 over refractions, so that RR ignores radiance scaling
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
    vec4 lanes[WF_HERO_LANES]; // --spectral hero: each lane's share and wavelength (hero_lanes)
#elif WF_HAS_DISPERSION
    float wavelength;  // nm, from the path's first dispersive vertex on; 0 while it is RGB
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    vec4 mis;          // pathMis: the camera subpath's MIS quantities (bdpt_state.glsl)
#endif
#if WF_RAY_CONES
    vec2 cone;         // the ray's cone: width at its origin, spread (ray_cones.glsl)
#endif
    // Out.
    vec3 radiance;     // emission found by this ray, weighted
    bool continues;
    bool connects;
    vec3 shadowOrigin;
    vec3 shadowSegment;  // to the light point: t in (0, 1)
    uint shadowSphere;   // the sphere light it ends on (segmentOccluded leaves it out)
    vec3 shadowRadiance; // added if the segment is unoccluded
#if WF_AOV
    vec4 aovAlbedoDistance; // the surface this ray found: base colour and distance (--aov)
    vec3 aovNormal;         // and its shading normal, facing the ray; zero on no surface
#endif
};

// Weight of emission found by a ray whose direction had BSDF density directionPdf (0: camera or
// a specular bounce, which light sampling cannot reproduce) and light density lightPdf.
float emissionWeight(float directionPdf, float lightPdf) {
#if WF_LIGHT_SAMPLING == 0
    return 1.0;
#elif WF_LIGHT_SAMPLING == 1
    return directionPdf == 0.0 || lightPdf == 0.0 ? 1.0 : 0.0;
#else
    return directionPdf == 0.0 ? 1.0 : powerHeuristic(directionPdf, lightPdf);
#endif
}

// --clamp: scale a contribution down so no channel exceeds the limit (biased, off by default).
vec3 clampContribution(vec3 c) {
    float peak = max(c.r, max(c.g, c.b));
    return params.clampRadiance > 0.0 && peak > params.clampRadiance
               ? c * (params.clampRadiance / peak) : c;
}

float vertexSample1D(PathVertex v, uint offset) {
    return sample1D(v.pixel, v.sampleIndex, bounceDimension(v.depth, offset), params.seed);
}

vec2 vertexSample2D(PathVertex v, uint offset) {
    return sample2D(v.pixel, v.sampleIndex, bounceDimension(v.depth, offset), params.seed);
}

// Emission from the environment or a sphere light; returns false when the path ends here.
bool shadeLightHit(inout PathVertex v) {
    float t = uintBitsToFloat(v.hit.x);
    if (v.hit.w == WF_MISS) {
#if WF_HAS_ENVIRONMENT
        float lightPdf = 0.0;
#if WF_HAS_EMITTERS && WF_LIGHT_SAMPLING != 0
        lightPdf = environmentLightPdf(v.direction);
#endif
        float weight = emissionWeight(v.previousPdf, lightPdf);
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
        // The emitter seen directly has no other strategy here (vcm_mis.h); the infinite
        // light takes the camera's quantities as they are, before any hit.
        weight = v.depth == 0u
                     ? 1.0
                     : vcmWeightEmitterHit(bdptMisConfig(v.sampleIndex), bdptMis(v.mis), lightPdf,
                                           lightPdf / (WF_PI * params.sceneRadius *
                                                       params.sceneRadius));
#endif
        v.radiance += clampContribution(v.beta * environmentRadiance(v.direction) * weight);
#endif
        return false;
    }
#if WF_HAS_SPHERE_LIGHTS
    // Sphere lights are pure emitters: add what leaves the outside and end the path.
    if ((v.hit.w & WF_SPHERE_HIT) != 0u) {
        PunctualLight light = lightAt(v.hit.w & ~WF_SPHERE_HIT);
        vec3 normal = normalize(v.origin + t * v.direction - light.position);
        float cosLight = dot(normal, -v.direction);
        if (cosLight > 0.0) {
            float lightPdf = 0.0;
#if WF_HAS_EMITTERS && WF_LIGHT_SAMPLING != 0
            if (light.emitter != WF_NO_EMITTER)
                lightPdf = sphereLightPdf(lightPmf(light.emitter, v.origin, v.previousNormal),
                                          light, v.origin, t, cosLight);
#endif
            float weight = emissionWeight(v.previousPdf, lightPdf);
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
            if (v.depth > 0u && light.emitter != WF_NO_EMITTER) {
                VcmSubpathMis mis = bdptMis(v.mis);
                vcmOnHit(bdptMisConfig(v.sampleIndex), mis, t * t, cosLight);
                float pmf = emitterAt(light.emitter).pmf;
                weight = vcmWeightEmitterHit(bdptMisConfig(v.sampleIndex), mis,
                                             lightPdf * cosLight / (t * t),
                                             sphereEmissionPdfW(pmf, light, cosLight));
            } else {
                weight = 1.0;
            }
#endif
            v.radiance += clampContribution(v.beta * sphereRadiance(light) * weight);
        }
        return false;
    }
#endif
    return true;
}

BsdfParams bsdfAt(SurfaceHit surface) {
    BsdfParams bsdf;
    bsdf.baseColor = surface.baseColor;
    bsdf.metallic = surface.metallic;
    bsdf.roughness = surface.roughness;
    bsdf.ior = surface.ior;
    bsdf.transmission = surface.transmission;
    bsdf.specular = surface.specular;
    bsdf.specularColor = surface.specularColor;
#if WF_HAS_IRIDESCENCE
    bsdf.iridescence = surface.iridescence;
    bsdf.iridescenceIor = surface.iridescenceIor;
    bsdf.iridescenceThickness = surface.iridescenceThickness;
#endif
#if WF_HAS_ANISOTROPY
    bsdf.anisotropy = surface.anisotropy; // along the shading frame's x axis (below)
#endif
#if WF_HAS_DIFFUSE_TRANSMISSION
    bsdf.diffuseTransmission = surface.diffuseTransmission;
    bsdf.diffuseTransmissionColor = surface.diffuseTransmissionColor;
#endif
    return bsdf;
}

#if WF_BSDF_LAYERS
BsdfLayers layersAt(SurfaceHit surface) {
#if WF_HAS_CLEARCOAT_NORMAL_MAPS
    BsdfLayers layers = BsdfLayers(0.0, 0.0, vec3(0.0), 0.0, vec3(0.0, 0.0, 1.0));
#else
    BsdfLayers layers = BsdfLayers(0.0, 0.0, vec3(0.0), 0.0);
#endif
#if WF_HAS_CLEARCOAT
    layers.clearcoat = surface.clearcoat;
    layers.clearcoatRoughness = surface.clearcoatRoughness;
#endif
#if WF_HAS_SHEEN
    layers.sheenColor = surface.sheenColor;
    layers.sheenRoughness = surface.sheenRoughness;
#endif
    return layers;
}
#endif
#include "wave/shading_frame.glsl"
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
#include "wave/hero_lanes.glsl"
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
#include "bidir/bdpt_connect.glsl"
// The last camera vertex shaded, for shade.comp's connections (bdpt_connect.glsl).
BdptCameraVertex bdptVertex;
#endif

void shadePathVertex(inout PathVertex v) {
    v.radiance = vec3(0.0);
    v.continues = false;
    v.connects = false;
    if (!shadeLightHit(v))
        return;

    vec3 wo = -v.direction;
#if WF_HAS_INSTANCES
    // x held the instance (intersectClosest); the direction is unit length.
    float t = instancedHitDistance(v.hit.x, v.hit.w, uintBitsToFloat(v.hit.y),
                                   uintBitsToFloat(v.hit.z), v.origin);
#else
    float t = uintBitsToFloat(v.hit.x);
#endif
#if WF_RAY_CONES
    float coneWidth = coneWidthAt(v.cone, t);
#else
    float coneWidth = 0.0;
#endif
    SurfaceHit surface = loadSurface(v.hit.x, v.hit.w, uintBitsToFloat(v.hit.y),
                                     uintBitsToFloat(v.hit.z), wo, coneWidth);
#if WF_HAS_VOLUME
    // KHR_materials_volume, Beer-Lambert: a ray that meets a transmissive surface from behind
    // has crossed that mesh's inside over t (world units). Exact for closed meshes that hold
    // no other surface; see README's Materials section for the rule's limits.
    if (!surface.frontFace && surfaceTransmits(surface))
        v.beta *= exp(-surface.absorption * t);
#endif
#if WF_GUIDING
    guideTakeHitPoint(v.path, surface.p);
#endif
#if WF_AOV
    v.aovAlbedoDistance = vec4(surface.baseColor, t);
    v.aovNormal = surface.ns;
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    VcmMisConfig misConfig = bdptMisConfig(v.sampleIndex);
    VcmSubpathMis mis = bdptMis(v.mis);
    vcmOnHit(misConfig, mis, t * t, abs(dot(wo, surface.ng)));
    bdptVertex.connectable = false;
#endif
    if (any(greaterThan(surface.emission, vec3(0.0)))) {
        float lightPdf = 0.0;
#if WF_HAS_TRIANGLE_EMITTERS && WF_LIGHT_SAMPLING != 0
        if (v.previousPdf > 0.0 && surface.emitter != WF_NO_EMITTER)
            lightPdf = triangleLightPdf(lightPmf(surface.emitter, v.origin, v.previousNormal),
                                        triangleAt(v.hit.w), v.origin, t, abs(dot(surface.ng, wo)));
#endif
        float weight = emissionWeight(v.previousPdf, lightPdf);
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
        weight = 1.0; // seen directly, or an emitter no light subpath can leave
#if WF_HAS_TRIANGLE_EMITTERS
        if (v.depth > 0u && surface.emitter != WF_NO_EMITTER) {
            // NEE's density of this point from the last vertex, lightPdf, in area measure; 0
            // after a Dirac bounce, where dVCM is 0 too and it weighs nothing.
            float cosLight = abs(dot(surface.ng, wo));
            Triangle emitting = triangleAt(v.hit.w);
            weight = vcmWeightEmitterHit(
                misConfig, mis, lightPdf * cosLight / (t * t),
                triangleEmissionPdfW(emitterAt(surface.emitter).pmf, emitting,
                                     materialAt(emitting.material), cosLight));
        }
#endif
#endif
        v.radiance += clampContribution(v.beta * surface.emission * weight);
    }
#if WF_INTEGRATOR == WF_INTEGRATOR_LIGHT
    return; // light tracing: the camera finds emitters seen directly, light subpaths the rest
#endif

    BsdfParams bsdf = bsdfAt(surface);
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
    // --spectral hero: the path's four wavelengths from its first dispersive vertex on;
    // bsdf takes the ior of the lane that samples (hero_lanes.glsl).
    HeroVertex hero = heroAt(v, surface, bsdf.ior);
    bsdf.ior = hero.ior[hero.lane];
#elif WF_HAS_DISPERSION
    // KHR_materials_dispersion (bsdf/dispersion.h): the path picks its wavelength at its first
    // dispersive vertex, before next-event estimation and the BSDF sample, so that both (and
    // every dispersive vertex after) bend it by n(lambda); the weight averages to (1, 1, 1).
    if (surface.dispersion > 0.0 && surface.transmission > 0.0) {
        if (v.wavelength == 0.0) {
            v.wavelength = sampleWavelength(vertexSample1D(v, WF_DIM_WAVELENGTH));
            v.beta *= dispersionWeight(v.wavelength);
        }
        bsdf.ior = dispersionIor(bsdf.ior, surface.dispersion, v.wavelength);
    }
#endif
#if WF_BSDF_LAYERS
    BsdfLayers layers = layersAt(surface);
#endif
    // The frame light subpaths and BDPT's light vertices build too (shading_frame.glsl).
    ShadingFrame frame = shadingFrameAt(surface);
    vec3 n = frame.n;
    vec3 tangent = frame.tangent;
    vec3 bitangent = frame.bitangent;
    vec3 geometricOutside = frame.outside;
    vec3 woLocal = toShadingFrame(frame, wo);
#if WF_BSDF_LAYERS && WF_HAS_CLEARCOAT && WF_HAS_CLEARCOAT_NORMAL_MAPS
    placeCoatNormal(layers, surface, frame);
#endif
#if WF_LIGHT_TREE
    // The light tree weighs lights by the side light can arrive from (both through glass or a
    // diffuse-transmitting sheet).
    float receiver = surfaceTransmits(surface) ? 0.0 : encodeReceiverNormal(n);
#else
    float receiver = 0.0;
#endif
#if WF_GUIDING
#if WF_BSDF_LAYERS
    bool guideHere = layeredHasNonDelta(bsdf, layers);
#else
    bool guideHere = bsdfHasNonDelta(bsdf);
#endif
    // Guided: vertices of bounce index below guide.maxDepth, and any vertex its ray reached by
    // a Dirac bounce (a caustic seen through glass); the rest sample the BSDF alone, where
    // the mixture's doubled weights would compound (docs/guiding.md, "Levers, one at a time",
    // "Guided vertices"). maxDepth 0: no vertex (training stopped where the guide did not
    // pay), not even the leaf's walk.
    guideHere = guideHere && guide.maxDepth > 0u &&
                (v.depth < guide.maxDepth || v.previousPdf == 0.0);
    uint guideNode = guideHere ? guideLeafNode(surface.p) : 0u;
    float leafFraction = guideHere ? guideLeafFraction(guideNode) : guide.bsdfFraction;
    // A leaf that learnt the BSDF alone (share 1) samples it alone, as an unguided vertex does,
    // but while training: its records still need the guide's density to learn again.
    guideHere = guideHere && (guide.training != 0u || leafFraction < 1.0);
    uint guideRoot = guideHere ? guideSpatial[guideNode].samplingRoot : 0u;
    vec3 guideOffset = vec3(0.0);
    float guideRadius = 0.0;
    if (guideHere)
        guideParallaxAt(guideNode, surface.p, guideOffset, guideRadius);
    // The leaf's share on both sides of MIS (NEE here, the continuation below).
    float guideFraction = guideHere ? leafFraction : guide.bsdfFraction;
#endif

#if WF_HAS_EMITTERS && WF_LIGHT_SAMPLING != 0
    // Next-event estimation: the connection adds one more path segment.
#if WF_BSDF_LAYERS
    bool hasNonDelta = layeredHasNonDelta(bsdf, layers);
#else
    bool hasNonDelta = bsdfHasNonDelta(bsdf);
#endif
    if (v.depth + 2u <= params.maxDepth && hasNonDelta) {
        LightSample light = sampleLight(vertexSample1D(v, WF_DIM_LIGHT_CHOICE),
                                        vertexSample2D(v, WF_DIM_LIGHT_POINT),
                                        vertexSample1D(v, WF_DIM_LIGHT_EXTRA), surface.p,
                                        receiver);
        vec3 wiLocal = vec3(dot(light.direction, tangent), dot(light.direction, bitangent),
                            dot(light.direction, n));
        if (light.pdf > 0.0) {
#if WF_BSDF_LAYERS
            vec3 f = layeredEval(bsdf, layers, woLocal, wiLocal);
#else
            vec3 f = bsdfEval(bsdf, woLocal, wiLocal);
#endif
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
            // Each lane's f; the BSDF side of MIS is the lanes' mixture (heroPdf below).
            vec3 heroF[WF_HERO_LANES];
            float heroPdf = 0.0;
            if (hero.on)
                f = heroEval(v, hero, bsdf WF_HERO_LAYERS_ARG, woLocal, wiLocal, heroF, heroPdf);
#endif
            float weight = 1.0;
#if WF_LIGHT_SAMPLING == 2 && WF_GUIDING
            if (!light.isDelta) {
#if WF_BSDF_LAYERS
                float directionPdf = layeredPdf(bsdf, layers, woLocal, wiLocal);
#else
                float directionPdf = bsdfPdf(bsdf, woLocal, wiLocal);
#endif
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
                directionPdf = hero.on ? heroPdf : directionPdf;
#endif
                // A leaf at share 1 (still walking while training, for its records) weighs the
                // BSDF's pdf alone: its walk here would be multiplied by 0.
                if (guideHere && guideFraction < 1.0)
                    directionPdf = guideMixturePdf(
                        directionPdf,
                        guidePdfAt(guideRoot, guideOffset, guideRadius, light.direction),
                        guideFraction);
                weight = powerHeuristic(light.pdf, directionPdf);
            }
#elif WF_LIGHT_SAMPLING == 2 && WF_HAS_DISPERSION && WF_SPECTRAL_HERO
            if (!light.isDelta)
                weight = powerHeuristic(light.pdf, hero.on ? heroPdf
                                                           : WF_HERO_PDF(bsdf, woLocal, wiLocal));
#elif WF_LIGHT_SAMPLING == 2
#if WF_BSDF_LAYERS
            if (!light.isDelta)
                weight = powerHeuristic(light.pdf, layeredPdf(bsdf, layers, woLocal, wiLocal));
#else
            if (!light.isDelta)
                weight = powerHeuristic(light.pdf, bsdfPdf(bsdf, woLocal, wiLocal));
#endif
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
            weight = vcmWeightNee(
                misConfig, mis, light.misPdfW,
                light.isDelta ? 0.0 : bdptPdf(WF_BDPT_LOBES(bsdf, layers), woLocal, wiLocal),
                bdptPdf(WF_BDPT_LOBES(bsdf, layers), wiLocal, woLocal), light.emissionPdfW,
                light.cosAtLight,
                abs(dot(light.direction, surface.ng)));
#endif
            vec3 contribution = v.beta * f * light.radiance * (abs(wiLocal.z) * weight / light.pdf);
            v.shadowOrigin =
                offsetRayOrigin(surface.p, surface.pError, geometricOutside, light.direction);
            v.shadowSegment = light.segmentEnd - v.shadowOrigin;
            v.shadowSphere = light.sphere;
            v.shadowRadiance = clampContribution(contribution);
            v.connects = any(greaterThan(contribution, vec3(0.0)));
        }
    }
#endif

#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
#if WF_BSDF_LAYERS
    bdptVertex.connectable = layeredHasNonDelta(bsdf, layers);
    bdptVertex.layers = layers;
#else
    bdptVertex.connectable = bsdfHasNonDelta(bsdf);
#endif
    bdptVertex.p = surface.p;
    bdptVertex.pError = surface.pError;
    bdptVertex.ng = surface.ng;
    bdptVertex.outside = geometricOutside;
    bdptVertex.tangent = tangent;
    bdptVertex.bitangent = bitangent;
    bdptVertex.n = n;
    bdptVertex.woLocal = woLocal;
    bdptVertex.beta = v.beta;
    bdptVertex.mis = mis;
    bdptVertex.sampleIndex = v.sampleIndex;
    bdptVertex.pixel = v.pixel;
    bdptVertex.bsdf = bsdf;
#endif
    if (v.depth + 1u >= params.maxDepth)
        return;
    BsdfSample s;
#if WF_GUIDING
    // The mixture's choice reuses the lobe dimension (rescaled), so the sample dimensions per
    // bounce stay those of the unguided renderer.
    float uLobe = vertexSample1D(v, WF_DIM_BSDF_LOBE);
    vec2 uDirection = vertexSample2D(v, WF_DIM_BSDF);
    bool fromGuide = guideHere && uLobe >= guideFraction;
    if (guideHere && !fromGuide)
        uLobe = min(uLobe / guideFraction, 0.99999994);
    if (!fromGuide) {
#if WF_BSDF_LAYERS
        if (!layeredSample(bsdf, layers, woLocal, uLobe, uDirection, s))
            return;
#else
        if (!bsdfSample(bsdf, woLocal, uLobe, uDirection, s))
            return;
#endif
    }
    vec3 wi;
    // What a training record keeps of the mixture: both densities and f |cos|.
    float recordBsdfPdf = 0.0, recordGuidePdf = 0.0, recordFCos = 0.0;
    if (guideHere) {
        // One quadtree walk per lane: the guide's sample, or its density at the BSDF's.
        // Either way through the leaf's centre (parallax): jacobian turns the quadtree's
        // density there into the density here.
        float jacobian = 1.0;
        vec2 x = fromGuide ? vec2(0.0)
                           : guideDirToSquare(guideParallaxToCentre(
                                 guideOffset, guideRadius,
                                 normalize(tangent * s.wi.x + bitangent * s.wi.y + n * s.wi.z),
                                 jacobian));
        float squarePdf;
        x = guideSampleOrPdfSquare(guideRoot, fromGuide, uDirection, x, squarePdf);
        if (fromGuide) {
            vec3 w = guideParallaxFromCentre(guideOffset, guideRadius, guideSquareToDir(x),
                                             jacobian);
            s.wi = vec3(dot(w, tangent), dot(w, bitangent), dot(w, n));
            s.isDelta = false;
            s.eta = 1.0; // only Russian roulette reads it: any value stays unbiased
        }
        wi = normalize(tangent * s.wi.x + bitangent * s.wi.y + n * s.wi.z);
        if (s.isDelta) {
            s.weight /= guideFraction; // a Dirac lobe only the BSDF's share can choose
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
            if (hero.on)
                s.weight = heroScatterDelta(v, hero, bsdf, woLocal, s, guideFraction);
#endif
        } else {
            // Either branch: f |cos| over the mixture's pdf, so that both sides of MIS see one
            // function of the direction (the NEE side evaluates the guide's pdf at the light's
            // direction; the walk's pdf is that function at this one).
#if WF_BSDF_LAYERS
            vec3 f = layeredEval(bsdf, layers, woLocal, s.wi);
            float directionPdf = layeredPdf(bsdf, layers, woLocal, s.wi);
#else
            vec3 f = bsdfEval(bsdf, woLocal, s.wi);
            float directionPdf = bsdfPdf(bsdf, woLocal, s.wi);
#endif
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
            vec3 heroF[WF_HERO_LANES];
            if (hero.on)
                f = heroEval(v, hero, bsdf WF_HERO_LAYERS_ARG, woLocal, s.wi, heroF,
                             directionPdf);
#endif
            float guideDensity = squarePdf * WF_GUIDE_INV_4PI * jacobian;
            s.pdf = guideMixturePdf(directionPdf, guideDensity, guideFraction);
            s.weight = s.pdf > 0.0 ? f * (abs(s.wi.z) / s.pdf) : vec3(0.0);
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
            if (hero.on)
                s.weight = heroScatter(v, heroF, abs(s.wi.z), s.pdf);
#endif
            recordBsdfPdf = directionPdf;
            recordGuidePdf = guideDensity;
            recordFCos = (f.r + f.g + f.b) * (1.0 / 3.0) * abs(s.wi.z);
        }
    } else {
        wi = normalize(tangent * s.wi.x + bitangent * s.wi.y + n * s.wi.z);
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
        if (hero.on)
            heroScatterSample(v, hero, bsdf WF_HERO_LAYERS_ARG, woLocal, s);
#endif
    }
#else
#if WF_BSDF_LAYERS
    if (!layeredSample(bsdf, layers, woLocal, vertexSample1D(v, WF_DIM_BSDF_LOBE),
                       vertexSample2D(v, WF_DIM_BSDF), s))
        return;
#else
    if (!bsdfSample(bsdf, woLocal, vertexSample1D(v, WF_DIM_BSDF_LOBE),
                    vertexSample2D(v, WF_DIM_BSDF), s))
        return;
#endif
    vec3 wi = normalize(tangent * s.wi.x + bitangent * s.wi.y + n * s.wi.z);
#if WF_HAS_DISPERSION && WF_SPECTRAL_HERO
    if (hero.on)
        heroScatterSample(v, hero, bsdf WF_HERO_LAYERS_ARG, woLocal, s);
#endif
#endif
#if WF_INTEGRATOR == WF_INTEGRATOR_BDPT
    float scatterReversePdf =
        s.isDelta ? s.pdf : bdptPdf(WF_BDPT_LOBES(bsdf, layers), s.wi, woLocal);
    vcmOnScatter(misConfig, mis, abs(dot(wi, surface.ng)), s.pdf, scatterReversePdf, s.isDelta);
    v.mis = bdptStored(mis);
#endif
    vec3 beta = v.beta * s.weight;
    float etaScale = v.etaScale * s.eta * s.eta;
    if (v.depth >= params.rrDepth) {
        // Survive with the throughput's largest channel (at most 1) and divide by it:
        // unbiased, and paths that carry little end early.
        float survive = min(max(beta.r, max(beta.g, beta.b)) * etaScale, 1.0);
        beta = vertexSample1D(v, WF_DIM_ROULETTE) < survive ? beta / survive : vec3(0.0);
    }
    // --min-throughput: the course's biased alternative to roulette.
    if (max(beta.r, max(beta.g, beta.b)) < params.minThroughput)
        beta = vec3(0.0);
    v.continues = any(greaterThan(beta, vec3(0.0)));
    if (v.continues) {
        v.origin = offsetRayOrigin(surface.p, surface.pError, geometricOutside, wi);
        v.direction = wi;
        v.previousPdf = s.isDelta ? 0.0 : s.pdf; // a Dirac bounce: emission counts in full
        v.previousNormal = receiver;
#if WF_GUIDING
        if (guideHere && !s.isDelta)
            guideKeepRecord(v.path, surface.p, wi, s.pdf, beta, recordBsdfPdf, recordGuidePdf,
                            recordFCos);
#endif
        v.beta = beta;
        v.etaScale = etaScale;
#if WF_RAY_CONES
        v.cone = coneAfterBounce(v.cone, coneWidth, v.previousPdf);
#endif
    }
}
