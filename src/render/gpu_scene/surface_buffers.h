// The GPU side of SurfaceData: per-triangle normals, tangents and UVs, the texture-reference
// table and the texels, each buffer created only when the scene uses it and bound as a texel
// buffer (surface_bindings.glsl). Texels are packed into up to WF_MAX_TEXEL_PAGES buffers
// ("pages") so that none passes the device's per-buffer limits (lavapipe: 128 MiB); an image
// too big for one page is halved until it fits.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "gpu/buffer.h"
#include "gpu/compute_program.h"
#include "render/gpu_scene/table_pages.h"
#include "scene/scene.h"

namespace wf {

class Context;

// Where each image goes: its page, first texel and size after any halving.
struct TexelPlacement {
    uint32_t page = 0;
    uint32_t offset = 0;
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t halvings = 0; // times the image was halved to fit a page
};

struct TexelPlan {
    std::vector<TexelPlacement> images;  // parallel to SurfaceData::images
    std::vector<uint64_t> pageTexels;    // texels per page
};

// Throws InputError naming the limit and the excess when the texels need more than
// WF_MAX_TEXEL_PAGES pages of `pageBytes`.
TexelPlan planTexels(const SurfaceData& surface, uint64_t pageBytes);

// The largest page the device can hold as one buffer and view as R32UI texels.
uint64_t texelPageBytes(const Context& context);

// The BVH builder reorders triangles; the per-triangle arrays must follow. Before the build,
// tagTriangles stores each triangle's index in its `pad`; afterwards followTriangleOrder
// permutes the arrays by those tags and clears them.
void tagTriangles(std::vector<Triangle>& triangles);
void followTriangleOrder(std::vector<Triangle>& triangles, SurfaceData& surface);

// Which code paths the surface data needs (the shader defines come from these).
struct SurfaceFeatures {
    bool textures = false;
    bool normals = false;
    bool texcoord1 = false;
    bool normalMaps = false;
    // Tangent frames bound for KHR_materials_anisotropy's direction (WF_HAS_TANGENTS), where
    // some material is anisotropic and the scene has them.
    bool tangents = false;
    bool vertexColors = false; // COLOR_0
    bool alphaMask = false; // some material is MASK or BLEND
    uint32_t texelPages = 0;
};
SurfaceFeatures surfaceFeatures(const SurfaceData& surface, const std::vector<Material>& materials,
                                uint64_t pageBytes);

class SurfaceBuffers {
public:
    SurfaceBuffers() = default;
    // The per-triangle arrays are cut at the triangle table's page boundaries
    // (`trianglePages`), so one page index serves them all.
    SurfaceBuffers(const Context& context, const SurfaceData& surface,
                   const SurfaceFeatures& features, const TablePages& trianglePages);

    void appendBindings(DescriptorBindings& bindings) const;
    void appendMemoryReport(std::vector<std::pair<std::string, uint64_t>>& report) const;

private:
    std::vector<Buffer> normals_; // a buffer per triangle page, each of these four
    std::vector<Buffer> tangents_;
    std::vector<Buffer> uv0_;
    std::vector<Buffer> uv1_;
    std::vector<Buffer> colors_;
    Buffer textureRefs_;
    std::vector<Buffer> texelPages_;
};

} // namespace wf
