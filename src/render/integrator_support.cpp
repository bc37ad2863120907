#include "render/integrator_support.h"

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

uint32_t defaultLightShare(Integrator integrator) {
    return integrator == Integrator::Bdpt ? 8u : 1u;
}

uint32_t lightSubpathsPerSample(const RenderSettings& settings, Integrator integrator,
                                bool motion, uint32_t pixelCount) {
    if (integrator == Integrator::Path || motion)
        return pixelCount;
    const uint64_t share =
        settings.lightShare > 0 ? settings.lightShare : defaultLightShare(integrator);
    return static_cast<uint32_t>((uint64_t(pixelCount) + share - 1) / share);
}

} // namespace wf
