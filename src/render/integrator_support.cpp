#include "render/integrator_support.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "errors.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/scene.h"
#include "shaders/bidir/camera_importance.h"

namespace wf {

void requireIntegratorSupport(const RenderSettings& settings, const PreparedScene& scene) {
    if (settings.integrator == Integrator::Path)
        return;
    const auto refuse = [&](const std::string& what) {
        throw UsageError(std::string("--integrator ") + integratorName(settings.integrator) +
                         ": " + what);
    };
    if (settings.megakernel)
        refuse("no megakernel of it exists; bench it without --compare-megakernel");
    if (settings.guiding)
        refuse("path guiding is not combined with light subpaths; use --guiding off");
    if (settings.pixelList)
        refuse("--target-error and adaptive sampling need per-pixel sample counts, which light "
               "splats do not keep; render a fixed --spp");
    for (const Material& m : scene.materials)
        if (m.clearcoat > 0.0f && m.clearcoatNormalTexture != WF_NO_TEXTURE)
            refuse("a clear coat with its own normal map is not reciprocal, and light subpaths "
                   "do not sample its adjoint yet");
    for (const Material& m : scene.materials)
        if (gpu_types::materialDisperses(m))
            refuse("KHR_materials_dispersion is traced by the path tracer only (light subpaths "
                   "carry no wavelength); use --integrator path");
    gpu_types::CameraGeometry camera{};
    camera.tanHalfFovY = std::tan(0.5f * scene.camera.yfov);
    camera.orthoHalfHeight = scene.camera.orthoHalfHeight;
    if (!gpu_types::cameraConnectable(camera))
        refuse("an orthographic camera has no lens that light paths can connect to");
}

namespace {

// Roughness 0 (which no texture raises) on a lobe that exists: a mirror, clear glass, a
// smooth coat.
bool hasDiracLobe(const Material& m) {
    const bool smooth = m.roughness <= 0.0f && m.anisotropyStrength <= 0.0f &&
                        (m.metallic > 0.0f || m.specular > 0.0f || m.transmission > 0.0f);
    return smooth || (m.clearcoat > 0.0f && m.clearcoatRoughness <= 0.0f);
}

} // namespace

uint32_t lightShareFor(const RenderSettings& settings, Integrator integrator, bool motion,
                       const std::vector<Material>& materials) {
    if (integrator == Integrator::Path || motion)
        return 1;
    if (settings.lightShare > 0)
        return settings.lightShare;
    const bool dirac = std::any_of(materials.begin(), materials.end(), hasDiracLobe);
    return integrator != Integrator::Light && !dirac ? 8u : 1u;
}

uint32_t lightSubpathsPerSample(uint32_t share, uint32_t pixelCount) {
    const uint64_t pixels = std::max<uint64_t>(share, 1);
    return static_cast<uint32_t>((pixelCount + pixels - 1) / pixels);
}

} // namespace wf
