#include "render/path_buffers.h"

#include "shaders/shared/render_types.h"

namespace wf {

using gpu_types::QueueCounters;
using gpu_types::RenderParams;

PathBuffers::PathBuffers(const Context& context, uint32_t pathCapacity, uint32_t pixelCount,
                         bool withShadowRays)
    : params(context, "params", sizeof(RenderParams)),
      counters(context, "queue counters", sizeof(QueueCounters),
               VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT),
      film(context, "film", uint64_t(pixelCount) * 16),
      rayOrigin(context, "ray origins", uint64_t(pathCapacity) * 16),
      rayDirection(context, "ray directions", uint64_t(pathCapacity) * 16),
      throughput(context, "throughput", uint64_t(pathCapacity) * 16),
      radiance(context, "path radiance", uint64_t(pathCapacity) * 16),
      hits(context, "hits", uint64_t(pathCapacity) * 16),
      rayQueues(context, "ray queues", uint64_t(pathCapacity) * 2 * 4) {
    if (!withShadowRays)
        return;
    shadowOrigin = Buffer(context, "shadow origins", uint64_t(pathCapacity) * 16);
    shadowDirection = Buffer(context, "shadow directions", uint64_t(pathCapacity) * 16);
    shadowRadiance = Buffer(context, "shadow radiance", uint64_t(pathCapacity) * 16);
    shadowQueue = Buffer(context, "shadow queue", uint64_t(pathCapacity) * 4);
}

void PathBuffers::appendBindings(
    DescriptorBindings& bindings) const {
    bindings.push_back({WF_BINDING_PARAMS, &params, BufferAccess::Uniform});
    bindings.push_back({WF_BINDING_COUNTERS, &counters});
    bindings.push_back({WF_BINDING_FILM, &film});
    bindings.push_back({WF_BINDING_RAY_ORIGIN, &rayOrigin});
    bindings.push_back({WF_BINDING_RAY_DIRECTION, &rayDirection});
    bindings.push_back({WF_BINDING_THROUGHPUT, &throughput});
    bindings.push_back({WF_BINDING_RADIANCE, &radiance});
    bindings.push_back({WF_BINDING_HITS, &hits});
    bindings.push_back({WF_BINDING_RAY_QUEUES, &rayQueues});
    // The same buffers again as texel views, through which the passes read them.
    bindings.push_back({WF_BINDING_RAY_ORIGIN_TEXELS, &rayOrigin, BufferAccess::UintTexels});
    bindings.push_back({WF_BINDING_RAY_DIRECTION_TEXELS, &rayDirection, BufferAccess::UintTexels});
    bindings.push_back({WF_BINDING_THROUGHPUT_TEXELS, &throughput, BufferAccess::UintTexels});
    bindings.push_back({WF_BINDING_RADIANCE_TEXELS, &radiance, BufferAccess::UintTexels});
    bindings.push_back({WF_BINDING_HITS_TEXELS, &hits, BufferAccess::UintTexels});
    if (shadowQueue) {
        bindings.push_back(
            {WF_BINDING_SHADOW_ORIGIN_TEXELS, &shadowOrigin, BufferAccess::UintTexels});
        bindings.push_back(
            {WF_BINDING_SHADOW_DIRECTION_TEXELS, &shadowDirection, BufferAccess::UintTexels});
        bindings.push_back(
            {WF_BINDING_SHADOW_RADIANCE_TEXELS, &shadowRadiance, BufferAccess::UintTexels});
        bindings.push_back({WF_BINDING_SHADOW_ORIGIN, &shadowOrigin});
        bindings.push_back({WF_BINDING_SHADOW_DIRECTION, &shadowDirection});
        bindings.push_back({WF_BINDING_SHADOW_RADIANCE, &shadowRadiance});
        bindings.push_back({WF_BINDING_SHADOW_QUEUE, &shadowQueue});
    }
}

void PathBuffers::appendMemoryReport(
    std::vector<std::pair<std::string, uint64_t>>& report) const {
    for (const Buffer* buffer :
         {&params, &counters, &film, &rayOrigin, &rayDirection, &throughput, &radiance, &hits,
          &shadowOrigin, &shadowDirection, &shadowRadiance, &rayQueues, &shadowQueue})
        if (*buffer)
            report.emplace_back(buffer->name(), buffer->size());
}

} // namespace wf
