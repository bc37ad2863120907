// Texture images: PNG and JPEG only, recognised by their first bytes (never by a file name or
// mimeType), dimensions bounded with stbi_info_from_memory before anything is decoded, and
// image bufferView ranges checked here because tinygltf 2.7.0 does not. Debian's stb_image 2.27
// still loops forever on some HDR input, so no other format ever reaches it.
#pragma once
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "scene/gltf/gltf_materials.h"

namespace tinygltf {
class Model;
}

namespace wf::gltf {

constexpr unsigned MAX_TEXTURE_SIDE = 16384;
constexpr size_t MAX_TEXTURE_PIXELS = size_t(1) << 26;  // 256 MiB as RGBA8
constexpr size_t MAX_TOTAL_TEXEL_BYTES = size_t(1) << 30; // all decoded images together

// Decodes PNG or JPEG bytes to RGBA8. Returns false, with `why` set, for any other format,
// oversized or corrupt data; never throws.
bool decodeImage(const unsigned char* bytes, size_t size, TextureImage& out, std::string& why);

// KHR_materials_pbrSpecularGlossiness: the metallic-roughness image (R 1, G roughness =
// 1 - glossinessFactor x the source's A, rounded to 8 bits, B metallic 0, A 1) of a decoded
// specularGlossinessTexture image.
TextureImage roughnessFromGlossiness(const TextureImage& source, float glossinessFactor);

// Decodes every image the materials use into surface.images and points surface.textureRefs
// at them. `encoded` holds the bytes tinygltf read for URI images (file or data:), by image
// index. An image that cannot be had is a warning: a base colour falls back to a magenta
// checker (visible on purpose), other uses drop the texture. Fails only on bad indices.
// The images made from decoded ones (MaterialTables::derived) follow them.
void loadImages(const tinygltf::Model& model, const std::string& file,
                const std::map<int, std::vector<unsigned char>>& encoded, MaterialTables& tables,
                SurfaceData& surface);

} // namespace wf::gltf
