// Which code paths and buffers a render needs, decided once from the scene and the settings
// ("model no more than a scene needs"), and the #defines that select them in the shaders.
#pragma once
#include <string>

#include "gpu/shader_compiler.h"
#include "render/samplers/samplers.h"
#include "render/gpu_scene/surface_buffers.h"
#include "render/gpu_scene/table_pages.h"

namespace wf {

struct PreparedScene;
struct RenderSettings;

enum class LightSampling { Bsdf = 0, Nee = 1, Mis = 2 };

// --integrator: the path tracer; light tracing (camera rays find the emitters they see, light
// subpaths connect to the camera for the rest; shaders/light_*.comp); bidirectional path
// tracing (both subpaths, every connection weighed by MIS; bidir/bdpt_state.glsl); vertex
// connection and merging (bdpt plus photon merges in the MIS, bidir/vcm_grid.glsl: consistent,
// not unbiased). Path, light and bdpt are WF_INTEGRATOR's values; vcm compiles bdpt's shaders
// with WF_VCM.
enum class Integrator { Path = 0, Light = 1, Bdpt = 2, Vcm = 3 };

// Both subpaths kept and connected (bdpt and vcm).
constexpr bool bidirectional(Integrator integrator) {
    return integrator == Integrator::Bdpt || integrator == Integrator::Vcm;
}

// --spectral, in scenes with KHR_materials_dispersion only (bsdf/dispersion.h): from its first
// dispersive vertex on a path carries one wavelength (single) or four, a hero and three a
// quarter of the range apart, weighed by spectral MIS at dispersive vertices (hero,
// WF_SPECTRAL_HERO; wave/hero_lanes.glsl). Images of the same expectation.
enum class SpectralSampling { Single, Hero };
SpectralSampling parseSpectralSampling(const std::string& name); // UsageError if unknown
const char* spectralSamplingName(SpectralSampling mode);

// How next-event estimation picks a light (--light-selection): uniformly, by power from one
// alias table, or by the light tree's importance at the shading point. Auto: the tree where
// the scene has kLightTreeMinLights or more lights for it, else power.
enum class LightSelection { Auto, Uniform, Power, Tree };
constexpr uint32_t kLightTreeMinLights = 4;

struct ShaderVariant {
    Integrator integrator = Integrator::Path; // WF_INTEGRATOR, defined only for light tracing
    // WF_BDPT_MIS_EXPONENT, defined only where bdpt or vcm take the balance heuristic (1; the
    // power heuristic, 2, is bdpt_state.glsl's default).
    bool bdptBalance = false;
    LightSampling lightSampling = LightSampling::Mis;
    bool nextEventEstimation = false; // a light table to sample, and shadow rays
    bool triangleEmitters = false;
    bool sphereLights = false;        // intersected by every ray, whatever the estimator
    bool deltaLights = false;         // point, spot, directional: reachable by NEE only
    bool environment = false;
    LightSelection lightSelection = LightSelection::Power; // never Auto: chooseVariant decides
    bool triangleSolidAngle = true;
    bool sphereSolidAngle = true;
    bool diffuseOnly = false;         // every material Lambertian: no specular layer code
    // Shading split by material kind (shade_kinds.h): bit k set for each kind present, in
    // scenes with two kinds or more (WF_SHADE_BINS); 0: one shade pass for every hit.
    uint32_t shadeKinds = 0;
    bool clearcoat = false;           // WF_HAS_CLEARCOAT: some material has a clear coat
    bool sheen = false;               // WF_HAS_SHEEN: some material has a sheen
    bool iridescence = false;         // WF_HAS_IRIDESCENCE: some material has a thin film
    bool anisotropy = false;          // WF_HAS_ANISOTROPY (defined only then): anisotropic GGX
    // WF_HAS_DIFFUSE_TRANSMISSION (defined only then): a Lambert lobe through the surface
    bool diffuseTransmission = false;
    // WF_HAS_DISPERSION (defined only then): glass with KHR_materials_dispersion; a path
    // carries one wavelength from its first dispersive vertex on (bsdf/dispersion.h)
    bool dispersion = false;
    bool heroWavelengths = false;     // WF_SPECTRAL_HERO (defined only then): --spectral hero
    bool volume = false;              // WF_HAS_VOLUME: some transmissive material absorbs
    bool specularTextures = false;    // WF_HAS_SPECULAR_TEXTURES: KHR_materials_specular maps
    // The layers' and volume's textures (issue 48), each only where a material with the layer
    // on has one: WF_HAS_CLEARCOAT_TEXTURES (coat, coat roughness), _CLEARCOAT_NORMAL_MAPS,
    // _SHEEN_TEXTURES (colour, roughness), _THICKNESS_TEXTURES.
    bool clearcoatTextures = false;
    bool clearcoatNormalMaps = false;
    bool sheenTextures = false;
    bool thicknessTextures = false;
    SurfaceFeatures surface;          // textures, normals, alpha: set by the renderer
    SamplerKind sampler = kDefaultSampler; // WF_SAMPLER (rng.h)
    bool randomizeSamples = true;     // WF_SAMPLER_RANDOMIZE: off for --no-randomize
    uint32_t errorReplicates = 1;     // WF_ERROR_REPLICATES (rng.h), defined only above 1
    bool packedStores = false;        // WF_PACKED_STORES: 64-bit stores, set by the renderer
    uint32_t registerStack = 0;       // WF_BVH_REGISTER_STACK: 8 or 16 entries in vectors, or 0
    bool aov = false;                 // WF_AOV: first-hit albedo, normal, distance
    bool secondMoment = false;        // WF_SECOND_MOMENT: radiance^2 per pixel (variance)
    bool adaptive = false;            // WF_ADAPTIVE: waves cover a list of pixels
    bool thinLens = false;            // WF_THIN_LENS: the camera has an aperture
    bool instances = false;           // WF_HAS_INSTANCES: a two-level BVH over instances
    bool rayCones = false;            // WF_RAY_CONES: texture LOD by ray cones (textured scenes)
    // WF_RAY_TRACING: intersect and shadow trace through the driver's acceleration structures
    // (--traversal rt); defined only then, so the BVH variants' shaders are as before.
    bool rayTracing = false;
    bool guiding = false;             // WF_GUIDING: the path guide's mixture and training
    bool motion = false;              // WF_MOTION: something moves within the shutter
    // Pixels per light subpath (--light-share; no define: RenderParams::lightPaths).
    uint32_t lightShare = 1;
    TablePages trianglePages;         // WF_TRIANGLE_PAGES, _SHIFT: set by the renderer
    TablePages bvhPages;              // WF_BVH_PAGES, _SHIFT: set by the renderer
    TablePages instancePages;         // WF_INSTANCE_PAGES, _SHIFT: set by the renderer

    uint32_t shadeBins() const; // passes shading by kind: 0 (none) or 2-3
    bool lightsBuffer() const { return sphereLights || deltaLights; }
    // Light tracing's passes exist: there is a light to trace from.
    bool lightSubpaths() const { return integrator != Integrator::Path && nextEventEstimation; }
    bool lightTree() const {
        return nextEventEstimation && lightSelection == LightSelection::Tree;
    }
    ShaderDefines defines() const;
    std::string describe() const;
};

ShaderVariant chooseVariant(const PreparedScene& scene, const RenderSettings& settings);
// The error replicates a render takes: settings.errorReplicates, but 1 for the independent
// sampler (independent already) and guided renders (render() combines their iterations).
uint32_t errorReplicatesFor(const RenderSettings& settings);

LightSampling parseLightSampling(const std::string& name); // UsageError if unknown
const char* lightSamplingName(LightSampling mode);
// "tree (light tree of N lights, depth D, built in X ms)", "power" or "uniform", for --verbose
// and the bench.
std::string describeLightSelection(const PreparedScene& scene, const ShaderVariant& variant);
LightSelection parseLightSelection(const std::string& name); // UsageError if unknown
Integrator parseIntegrator(const std::string& name); // UsageError if unknown
const char* integratorName(Integrator integrator);
const char* lightSelectionName(LightSelection selection);

} // namespace wf
