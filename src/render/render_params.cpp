#include "render/render_params.h"

#include <algorithm>
#include <cmath>

#include "errors.h"
#include "gpu/context.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/integrator_support.h"
#include "render/path_buffers.h"

namespace wf {

using gpu_types::RenderParams;

gpu_types::vec3 cameraRight(const Camera& camera) {
    return glm::normalize(glm::cross(camera.forward, camera.up));
}

ShaderVariant deviceVariant(const Context& context, const PreparedScene& scene,
                            const RenderSettings& settings) {
    ShaderVariant variant = chooseVariant(scene, settings);
    variant.surface = surfaceFeatures(scene.surface, scene.materials, texelPageBytes(context));
    variant.rayCones = variant.surface.textures && settings.textureLod;
    variant.packedStores = settings.packedStores && context.shaderInt64();
    variant.rayTracing = settings.traversal == Traversal::RayTracing && !settings.megakernel;
    if (variant.rayTracing && !context.rayTracingEnabled())
        throw UsageError("--traversal rt: ray tracing is not enabled on device '" +
                         context.deviceName() + "'");
    if (variant.rayTracing && variant.motion)
        throw UsageError("--traversal rt: motion blur (--shutter) is traced by the project's "
                         "BVH only; use --traversal bvh");
    variant.guiding = settings.guiding;
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    const uint64_t pageBytes =
        settings.tablePageBytes > 0
            ? settings.tablePageBytes
            : std::min<uint64_t>(limits.maxStorageBufferRange,
                                 uint64_t(limits.maxTexelBufferElements) * 16);
    variant.trianglePages =
        tablePaging(scene.triangles.size(), sizeof(Triangle), pageBytes, "triangles");
    variant.bvhPages =
        tablePaging(scene.bvhPairs.size(), sizeof(BvhPair), pageBytes, "BVH nodes");
    variant.instancePages =
        tablePaging(scene.instances.size(), sizeof(Instance), pageBytes, "instances");
    return variant;
}

RenderParams renderParams(const PreparedScene& scene, const Camera& camera,
                          const RenderSettings& settings, const ShaderVariant& variant,
                          uint32_t pixelCount, uint32_t pathCapacity) {
    RenderParams params{};
    params.cameraPosition = camera.position;
    params.tanHalfFovY = std::tan(0.5f * camera.yfov);
    params.cameraForward = camera.forward;
    params.aspect = float(settings.width) / float(settings.height);
    params.cameraUp = camera.up;
    params.seed = settings.seed;
    params.cameraRight = cameraRight(camera);
    params.maxDepth = settings.maxDepth;
    params.width = settings.width;
    params.height = settings.height;
    params.pixelCount = pixelCount;
    params.rrDepth = settings.rrDepth;
    params.emitterCount = static_cast<uint32_t>(scene.lights.emitters.size()) +
                          (variant.lightTree() ? 1u : 0u); // the tree's own slot
    params.pathCapacity = pathCapacity;
    params.sphereLightCount = scene.lights.sphereLights;
    params.environmentEmitter = scene.lights.environmentEmitter;
    params.sceneCenter = scene.bounds.center;
    params.sceneRadius = scene.bounds.radius;
    params.environmentWidth = scene.environment.width;
    params.environmentHeight = scene.environment.height;
    params.minThroughput = settings.minThroughput;
    params.clampRadiance = settings.clampRadiance;
    params.lensRadius = 0.5f * camera.aperture;
    params.focusDistance = camera.focusDistance;
    params.orthoHalfHeight = camera.orthoHalfHeight;
    params.motionSegments = scene.motionSegments;
    // A camera set since (the viewer's) has no keys: it stays where it is put.
    params.cameraMotionKeys = camera.motion.empty() ? 0u : scene.cameraMotionKeys;
    params.lightPaths = lightSubpathsPerSample(variant.lightShare, pixelCount);
    if (variant.integrator == Integrator::Vcm) {
        params.mergeRadius = settings.vcmRadius * scene.bounds.radius;
        params.mergeCells = PathBuffers::mergeCells(
            pathCapacity, PathBuffers::bdptLightVertices(variant, settings.maxDepth));
    }
    return params;
}

} // namespace wf
