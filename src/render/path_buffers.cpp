#include "render/path_buffers.h"

#include <algorithm>
#include <bit>

#include "shaders/types/render_types.h"

namespace wf {

using gpu_types::QueueCounters;
using gpu_types::RenderParams;

uint32_t PathBuffers::bdptLightVertices(const ShaderVariant& variant, uint32_t maxDepth) {
    if (!variant.lightSubpaths() || !bidirectional(variant.integrator))
        return 0;
    // Light bounce d connects to a camera vertex as a path of d + 3 segments or more, and
    // merges with one as a path of d + 2 or more (bdptKeepsLightVertex).
    const uint32_t shortest = variant.integrator == Integrator::Vcm ? 2 : 3;
    return maxDepth >= shortest ? maxDepth - shortest + 1 : 0;
}

uint32_t PathBuffers::mergeCells(uint32_t pathCapacity, uint32_t lightVertices) {
    // About one cell per light vertex (most lists short), a power of two for the hash's mask.
    const uint64_t vertices = uint64_t(pathCapacity) * lightVertices;
    return std::bit_ceil(uint32_t(std::clamp<uint64_t>(vertices, 1u << 10, 1u << 23)));
}

PathBuffers::PathBuffers(const Context& context, uint32_t pathCapacity, uint32_t pixelCount,
                         PathStateUse use, const ShaderVariant& variant, uint32_t maxDepth)
    : params(context, "params", sizeof(RenderParams)),
      // Ray-traced passes read their trace arguments by address.
      counters(context, "queue counters", sizeof(QueueCounters),
               VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                   (variant.rayTracing ? VK_BUFFER_USAGE_SHADER_DEVICE_ADDRESS_BIT : 0)),
      film(context, "film", uint64_t(pixelCount) * 16),
      radiance(context, "path radiance", uint64_t(pathCapacity) * 16) {
    if (variant.secondMoment)
        momentFilm = Buffer(context, "moment film", uint64_t(pixelCount) * 16);
    if (variant.errorReplicates > 1) {
        replicates = variant.errorReplicates;
        replicateFilm = Buffer(context, "replicate film",
                               uint64_t(pixelCount) * (replicates - 1) * 16);
    }
    if (variant.adaptive)
        activePixels = Buffer(context, "active pixels", uint64_t(pixelCount) * 4);
    if (use == PathStateUse::Megakernel)
        return; // its paths live in registers from camera to film
    if (variant.aov) {
        aovPaths = Buffer(context, "aov paths", uint64_t(pathCapacity) * 32);
        aovFilm = Buffer(context, "aov film", uint64_t(pixelCount) * 32);
    }
    if (variant.rayCones)
        rayCones = Buffer(context, "ray cones", uint64_t(pathCapacity) * 8);
    rayOrigin = Buffer(context, "ray origins", uint64_t(pathCapacity) * 16);
    rayDirection = Buffer(context, "ray directions", uint64_t(pathCapacity) * 16);
    throughput = Buffer(context, "throughput", uint64_t(pathCapacity) * 16);
    hits = Buffer(context, "hits", uint64_t(pathCapacity) * 16);
    rayQueues = Buffer(context, "ray queues", uint64_t(pathCapacity) * 2 * 4);
    if (variant.motion)
        rayTime = Buffer(context, "ray times", uint64_t(pathCapacity) * 4);
    if (variant.dispersion) // --spectral hero: four lanes of (share, wavelength) per path
        pathWavelength = Buffer(context, "path wavelengths",
                                uint64_t(pathCapacity) * (variant.heroWavelengths ? 64 : 4));
    if (variant.shadeKinds != 0) // at most 3 x 4 bytes x 4 M paths: within 128 MiB
        kindQueues =
            Buffer(context, "shade bins", uint64_t(pathCapacity) * variant.shadeBins() * 4);
    if (variant.lightSubpaths()) {
        lightFilm = Buffer(context, "light film", uint64_t(pathCapacity) * 24);
        lightFilm.upload(std::vector<uint32_t>(size_t(pathCapacity) * 6, 0u));
    }
    const uint64_t lightVertices = bdptLightVertices(variant, maxDepth);
    if (variant.lightSubpaths() && bidirectional(variant.integrator)) {
        pathMis = Buffer(context, "path mis", uint64_t(pathCapacity) * 16);
        lightDepths = Buffer(context, "light depths", uint64_t(pathCapacity) * 4);
        // Zero entries still bind (a depth-2 render keeps no light vertex).
        const uint64_t entries = std::max<uint64_t>(1, uint64_t(pathCapacity) * lightVertices);
        lightVertexHits = Buffer(context, "light vertex hits", entries * 16);
        lightVertexDirections = Buffer(context, "light vertex directions", entries * 16);
        lightVertexThroughputs = Buffer(context, "light vertex throughputs", entries * 16);
        if (variant.integrator == Integrator::Vcm) {
            lightVertexPositions = Buffer(context, "light vertex positions", entries * 16);
            mergeLists = Buffer(context, "merge lists",
                                (mergeCells(pathCapacity, lightVertices) + entries) * 4);
        }
    }
    if (use != PathStateUse::WavefrontWithShadowRays)
        return;
    // BDPT queues a camera vertex's NEE and its connections in one bounce (VCM's last light
    // vertex merges only).
    const uint64_t connected =
        variant.integrator == Integrator::Vcm && lightVertices > 0 ? lightVertices - 1
                                                                   : lightVertices;
    const uint64_t shadowEntries = uint64_t(pathCapacity) * (1 + connected);
    shadowOrigin = Buffer(context, "shadow origins", shadowEntries * 16);
    shadowDirection = Buffer(context, "shadow directions", shadowEntries * 16);
    shadowRadiance = Buffer(context, "shadow radiance", shadowEntries * 16);
}

uint64_t PathBuffers::lightSubpathBytes(uint32_t pathCapacity) const {
    uint64_t bytes = 0;
    for (const Buffer* buffer : {&lightFilm, &pathMis, &lightDepths, &lightVertexHits,
                                 &lightVertexDirections, &lightVertexThroughputs,
                                 &lightVertexPositions, &mergeLists})
        if (*buffer)
            bytes += buffer->size();
    if (lightFilm && shadowOrigin) // BDPT's wider shadow queue
        for (const Buffer* buffer : {&shadowOrigin, &shadowDirection, &shadowRadiance})
            bytes += buffer->size() - uint64_t(pathCapacity) * 16;
    return bytes;
}

void PathBuffers::appendBindings(DescriptorBindings& bindings) const {
    bindings.push_back({WF_BINDING_PARAMS, &params, BufferAccess::Uniform});
    const DescriptorBinding all[] = {
        {WF_BINDING_COUNTERS, &counters},
        {WF_BINDING_FILM, &film},
        {WF_BINDING_RAY_ORIGIN, &rayOrigin},
        {WF_BINDING_RAY_DIRECTION, &rayDirection},
        {WF_BINDING_THROUGHPUT, &throughput},
        {WF_BINDING_RADIANCE, &radiance},
        {WF_BINDING_HITS, &hits},
        {WF_BINDING_RAY_QUEUES, &rayQueues},
        {WF_BINDING_AOV_PATHS, &aovPaths},
        {WF_BINDING_AOV_FILM, &aovFilm},
        {WF_BINDING_MOMENT_FILM, &momentFilm},
        {WF_BINDING_ACTIVE_PIXELS, &activePixels},
        {WF_BINDING_REPLICATE_FILM, &replicateFilm},
        {WF_BINDING_SHADOW_ORIGIN, &shadowOrigin},
        {WF_BINDING_SHADOW_DIRECTION, &shadowDirection},
        {WF_BINDING_SHADOW_RADIANCE, &shadowRadiance},
        // The path state again as texel views, through which the passes read it.
        {WF_BINDING_RAY_ORIGIN_TEXELS, &rayOrigin, BufferAccess::UintTexels},
        {WF_BINDING_RAY_DIRECTION_TEXELS, &rayDirection, BufferAccess::UintTexels},
        {WF_BINDING_THROUGHPUT_TEXELS, &throughput, BufferAccess::UintTexels},
        {WF_BINDING_RADIANCE_TEXELS, &radiance, BufferAccess::UintTexels},
        {WF_BINDING_HITS_TEXELS, &hits, BufferAccess::UintTexels},
        {WF_BINDING_SHADOW_ORIGIN_TEXELS, &shadowOrigin, BufferAccess::UintTexels},
        {WF_BINDING_SHADOW_DIRECTION_TEXELS, &shadowDirection, BufferAccess::UintTexels},
        {WF_BINDING_SHADOW_RADIANCE_TEXELS, &shadowRadiance, BufferAccess::UintTexels},
        {WF_BINDING_RAY_QUEUE_TEXELS, &rayQueues, BufferAccess::Uint1Texels},
        {WF_BINDING_RAY_CONES, &rayCones},
        {WF_BINDING_RAY_CONE_TEXELS, &rayCones, BufferAccess::Uint2Texels},
        {WF_BINDING_KIND_QUEUES, &kindQueues},
        {WF_BINDING_KIND_QUEUE_TEXELS, &kindQueues, BufferAccess::Uint1Texels},
        {WF_BINDING_RAY_TIME, &rayTime},
        {WF_BINDING_PATH_WAVELENGTH, &pathWavelength},
        {WF_BINDING_LIGHT_FILM, &lightFilm},
        {WF_BINDING_PATH_MIS, &pathMis},
        {WF_BINDING_LIGHT_DEPTHS, &lightDepths},
        {WF_BINDING_LIGHT_VERTEX_HITS, &lightVertexHits},
        {WF_BINDING_LIGHT_VERTEX_DIRECTIONS, &lightVertexDirections},
        {WF_BINDING_LIGHT_VERTEX_THROUGHPUTS, &lightVertexThroughputs},
        {WF_BINDING_LIGHT_VERTEX_POSITIONS, &lightVertexPositions},
        {WF_BINDING_MERGE_LISTS, &mergeLists},
    };
    for (const DescriptorBinding& binding : all)
        if (*binding.buffer)
            bindings.push_back(binding);
}

void PathBuffers::appendMemoryReport(
    std::vector<std::pair<std::string, uint64_t>>& report) const {
    for (const Buffer* buffer :
         {&params, &counters, &film, &rayOrigin, &rayDirection, &throughput, &radiance, &hits,
          &shadowOrigin, &shadowDirection, &shadowRadiance, &rayQueues, &aovPaths, &aovFilm,
          &momentFilm, &replicateFilm, &activePixels, &rayCones, &kindQueues, &rayTime, &pathWavelength,
          &lightFilm, &pathMis, &lightDepths, &lightVertexHits, &lightVertexDirections,
          &lightVertexThroughputs, &lightVertexPositions, &mergeLists})
        if (*buffer)
            report.emplace_back(buffer->name(), buffer->size());
}

} // namespace wf
