// What a renderer hands the shaders about its scene: the shader variant, chooseVariant's
// choice completed by what the device allows (texel pages, int64 stores, ray tracing, table
// paging), and the RenderParams block (camera, image, lights, limits) uploaded on every change
// of camera, scene, seed or sample offset.
#pragma once
#include <cstdint>

#include "render/render_settings.h"
#include "render/shader_variant.h"
#include "scene/scene.h"
#include "shaders/types/render_types.h"

namespace wf {

class Context;
struct PreparedScene;

// The variant a renderer of `scene` with `settings` runs on `context`'s device; UsageError
// where the settings ask for what the device or the traversal cannot do.
ShaderVariant deviceVariant(const Context& context, const PreparedScene& scene,
                            const RenderSettings& settings);

// The parameters the passes read: `camera` (which may differ from the scene's) looking at
// `scene`, with `settings`' image, seed and limits.
gpu_types::RenderParams renderParams(const PreparedScene& scene, const Camera& camera,
                                     const RenderSettings& settings, const ShaderVariant& variant,
                                     uint32_t pixelCount, uint32_t pathCapacity);

// The camera looking at the scene: the file's, with the image's aspect.
gpu_types::vec3 cameraRight(const Camera& camera);

} // namespace wf
