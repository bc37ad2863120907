#include "render/gpu_scene/surface_buffers.h"

#include <algorithm>
#include <cstdio>

#include "errors.h"
#include "gpu/context.h"
#include "scene/mip_chain.h"

namespace wf {
namespace {

template <typename T>
Buffer uploadArray(const Context& context, const char* name, const std::vector<T>& values) {
    Buffer buffer(context, name, values.size() * sizeof(T));
    buffer.upload(values);
    return buffer;
}

// 2x2 box filter per channel (edges of odd sizes repeat the last texel).
TextureImage halve(const TextureImage& in) {
    TextureImage out;
    out.width = std::max(1u, in.width / 2);
    out.height = std::max(1u, in.height / 2);
    out.rgba.resize(size_t(out.width) * out.height);
    for (uint32_t y = 0; y < out.height; ++y) {
        for (uint32_t x = 0; x < out.width; ++x) {
            uint32_t sum[4] = {0, 0, 0, 0};
            for (uint32_t k = 0; k < 4; ++k) {
                const uint32_t sx = std::min(2 * x + (k & 1), in.width - 1);
                const uint32_t sy = std::min(2 * y + (k >> 1), in.height - 1);
                const uint32_t texel = in.rgba[size_t(sy) * in.width + sx];
                for (int c = 0; c < 4; ++c) {
                    sum[c] += texel >> (8 * c) & 0xffu;
                }
            }
            uint32_t texel = 0;
            for (int c = 0; c < 4; ++c) {
                texel |= ((sum[c] + 2) / 4) << (8 * c);
            }
            out.rgba[size_t(y) * out.width + x] = texel;
        }
    }
    return out;
}

// Images some reference reads as colour get their mip chain averaged as linear values. An
// image used both as colour and as data (rare) gets the colour chain.
std::vector<bool> srgbImages(const SurfaceData& surface) {
    std::vector<bool> srgb(surface.images.size(), false);
    for (size_t r = 0; r < surface.textureRefs.size() && r < surface.refImage.size(); ++r)
        if (surface.refImage[r] < srgb.size() && (surface.textureRefs[r].flags & WF_TEXTURE_SRGB))
            srgb[surface.refImage[r]] = true;
    return srgb;
}

} // namespace

TexelPlan planTexels(const SurfaceData& surface, uint64_t pageBytes) {
    // uint offsets index a page in the shader, so pages stay below 2^32 texels either way.
    const uint64_t pageTexels = std::min<uint64_t>(pageBytes, uint64_t(1) << 30) / 4;
    TexelPlan plan;
    uint64_t total = 0;
    for (const TextureImage& image : surface.images) {
        TexelPlacement place;
        place.width = image.width;
        place.height = image.height;
        // Each image is followed by its mip chain in the same page (textures.glsl finds the
        // levels from the size alone).
        while (mipChainTexels(place.width, place.height) > pageTexels) {
            place.width = std::max(1u, place.width / 2);
            place.height = std::max(1u, place.height / 2);
            ++place.halvings;
        }
        const uint64_t texels = mipChainTexels(place.width, place.height);
        if (plan.pageTexels.empty() || plan.pageTexels.back() + texels > pageTexels) {
            plan.pageTexels.push_back(0);
        }
        place.page = uint32_t(plan.pageTexels.size() - 1);
        place.offset = uint32_t(plan.pageTexels.back());
        plan.pageTexels.back() += texels;
        total += texels;
        plan.images.push_back(place);
    }
    if (plan.pageTexels.size() > WF_MAX_TEXEL_PAGES) {
        const uint64_t limit = WF_MAX_TEXEL_PAGES * pageTexels * 4;
        throw InputError("the scene's textures need " + std::to_string((total * 4) >> 20) +
                         " MiB, over the " + std::to_string(limit >> 20) + " MiB that " +
                         std::to_string(WF_MAX_TEXEL_PAGES) + " texel buffers of " +
                         std::to_string((pageTexels * 4) >> 20) + " MiB (the device's limit) " +
                         "hold, by " + std::to_string((total * 4 - limit) >> 20) +
                         " MiB; use smaller images");
    }
    return plan;
}

uint64_t texelPageBytes(const Context& context) {
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    return std::min<uint64_t>(limits.maxStorageBufferRange,
                              uint64_t(limits.maxTexelBufferElements) * 4);
}

void tagTriangles(std::vector<Triangle>& triangles) {
    for (size_t i = 0; i < triangles.size(); ++i)
        triangles[i].pad = uint32_t(i);
}

void followTriangleOrder(std::vector<Triangle>& triangles, SurfaceData& surface) {
    auto permute = [&](auto& array) {
        if (array.empty())
            return;
        auto old = std::move(array);
        array.resize(old.size());
        for (size_t i = 0; i < triangles.size(); ++i)
            array[i] = old[triangles[i].pad];
    };
    permute(surface.normals);
    permute(surface.tangents);
    permute(surface.uv0);
    permute(surface.uv1);
    permute(surface.colors);
    for (Triangle& t : triangles)
        t.pad = 0;
}

SurfaceFeatures surfaceFeatures(const SurfaceData& surface, const std::vector<Material>& materials,
                                uint64_t pageBytes) {
    SurfaceFeatures f;
    f.textures = !surface.textureRefs.empty() && !(surface.uv0.empty() && surface.uv1.empty());
    f.normals = !surface.normals.empty();
    f.texcoord1 = f.textures && !surface.uv1.empty();
    f.normalMaps = !surface.tangents.empty() && f.textures && f.normals;
    f.vertexColors = !surface.colors.empty();
    for (const Material& m : materials) {
        f.alphaMask |= (m.flags & (WF_MATERIAL_ALPHA_MASK | WF_MATERIAL_ALPHA_BLEND)) != 0;
        f.tangents |= m.anisotropyStrength > 0.0f && !surface.tangents.empty();
    }
    if (f.textures)
        f.texelPages = uint32_t(planTexels(surface, pageBytes).pageTexels.size());
    return f;
}

SurfaceBuffers::SurfaceBuffers(const Context& context, const SurfaceData& surface,
                               const SurfaceFeatures& features, const TablePages& trianglePages) {
    if (features.normals)
        normals_ = uploadPages(context, "vertex normals", surface.normals, trianglePages);
    if (features.normalMaps || features.tangents)
        tangents_ = uploadPages(context, "vertex tangents", surface.tangents, trianglePages);
    if (features.vertexColors)
        colors_ = uploadPages(context, "vertex colours", surface.colors, trianglePages);
    if (!features.textures)
        return;
    // Without UVs, one zero entry a page: the variant reads them, no texture lookup uses them.
    uv0_ = uploadPages(context, "texcoords 0", surface.uv0, trianglePages);
    if (features.texcoord1)
        uv1_ = uploadPages(context, "texcoords 1", surface.uv1, trianglePages);

    const uint64_t pageBytes = texelPageBytes(context);
    const TexelPlan plan = planTexels(surface, pageBytes);
    std::vector<TextureRef> refs = surface.textureRefs;
    for (size_t r = 0; r < refs.size(); ++r) {
        const uint32_t image = surface.refImage[r];
        const TexelPlacement place = image < plan.images.size() ? plan.images[image]
                                                                : TexelPlacement{};
        refs[r].page = place.page;
        refs[r].offset = place.offset;
        refs[r].width = place.width;
        refs[r].height = place.height;
        refs[r].levels = mipLevelCount(place.width, place.height);
    }
    const std::vector<bool> srgb = srgbImages(surface);
    textureRefs_ = uploadArray(context, "texture refs", refs);
    for (size_t page = 0; page < plan.pageTexels.size(); ++page) {
        std::vector<uint32_t> texels(plan.pageTexels[page]);
        for (size_t i = 0; i < plan.images.size(); ++i) {
            const TexelPlacement& place = plan.images[i];
            if (place.page != page)
                continue;
            TextureImage scaled;
            const TextureImage* image = &surface.images[i];
            for (uint32_t h = 0; h < place.halvings; ++h) {
                scaled = halve(*image);
                image = &scaled;
            }
            if (place.halvings > 0)
                std::fprintf(stderr, "warning: %s halved %u times to fit a %llu MiB buffer\n",
                             surface.images[i].name.c_str(), place.halvings,
                             static_cast<unsigned long long>(pageBytes >> 20));
            std::copy(image->rgba.begin(), image->rgba.end(), texels.begin() + place.offset);
            size_t next = place.offset + image->rgba.size();
            for (const TextureImage& level : buildMipChain(*image, srgb[i])) {
                std::copy(level.rgba.begin(), level.rgba.end(), texels.begin() + next);
                next += level.rgba.size();
            }
        }
        const std::string name = "texels " + std::to_string(page);
        texelPages_.push_back(uploadArray(context, name.c_str(), texels));
    }
}

// All read-only at scattered indices, so texel buffers (surface_bindings.glsl unpacks them).
void SurfaceBuffers::appendBindings(DescriptorBindings& bindings) const {
    bindPages(bindings, normals_, WF_BINDING_NORMALS, WF_BINDING_NORMAL_PAGE1);
    bindPages(bindings, tangents_, WF_BINDING_TANGENTS, WF_BINDING_TANGENT_PAGE1);
    bindPages(bindings, colors_, WF_BINDING_VERTEX_COLORS, WF_BINDING_VERTEX_COLOR_PAGE1);
    bindPages(bindings, uv0_, WF_BINDING_TEXCOORDS0, WF_BINDING_TEXCOORD0_PAGE1,
              BufferAccess::Uint2Texels);
    bindPages(bindings, uv1_, WF_BINDING_TEXCOORDS1, WF_BINDING_TEXCOORD1_PAGE1,
              BufferAccess::Uint2Texels);
    if (textureRefs_)
        bindings.push_back({WF_BINDING_TEXTURE_REFS, &textureRefs_, BufferAccess::UintTexels});
    for (size_t page = 0; page < texelPages_.size(); ++page)
        bindings.push_back(
            {WF_BINDING_TEXELS0 + uint32_t(page), &texelPages_[page], BufferAccess::Uint1Texels});
}

void SurfaceBuffers::appendMemoryReport(
    std::vector<std::pair<std::string, uint64_t>>& report) const {
    for (const std::vector<Buffer>* pages : {&normals_, &tangents_, &uv0_, &uv1_, &colors_})
        for (const Buffer& page : *pages)
            report.emplace_back(page.name(), page.size());
    if (textureRefs_)
        report.emplace_back(textureRefs_.name(), textureRefs_.size());
    for (const Buffer& page : texelPages_)
        report.emplace_back(page.name(), page.size());
}

} // namespace wf
