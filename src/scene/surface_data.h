// What a scene may carry beyond flat triangles: per-triangle vertex attributes (shading
// normals, tangents, two UV sets, vertex colours) and decoded textures. Every array is either empty (the scene
// does not need it, and the GPU gets no buffer for it) or holds one entry per triangle, in the
// same order as Scene::triangles.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "shaders/types/texture_types.h"

namespace wf {

using gpu_types::TextureRef;
using gpu_types::TriangleColors;
using gpu_types::TriangleNormals;
using gpu_types::TriangleTangents;
using gpu_types::TriangleUvs;

// An image decoded to RGBA8 (one uint per texel, little-endian R first), rows top first.
struct TextureImage {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint32_t> rgba;
    std::string name; // for messages: "image 3 (wood.png)"
};

struct SurfaceData {
    std::vector<TriangleNormals> normals;   // smooth shading normals, or empty
    std::vector<TriangleTangents> tangents; // only when a normal map is used
    std::vector<TriangleUvs> uv0;           // only when a texture is used
    std::vector<TriangleUvs> uv1;           // only when a texture reads TEXCOORD_1
    std::vector<TriangleColors> colors;     // COLOR_0, only when some primitive has it
    // Material texture fields index `textureRefs`; refImage[i] is the image of textureRefs[i]
    // (its page and offset are assigned when the texels are uploaded).
    std::vector<TextureRef> textureRefs;
    std::vector<uint32_t> refImage;
    std::vector<TextureImage> images;

    uint64_t texelBytes() const {
        uint64_t bytes = 0;
        for (const TextureImage& image : images)
            bytes += uint64_t(image.rgba.size()) * 4;
        return bytes;
    }
};

} // namespace wf
