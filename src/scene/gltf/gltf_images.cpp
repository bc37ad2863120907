// Image bytes to RGBA8 texels with stb_image (Debian's libstb; PNG, JPEG) and libwebp (WebP,
// EXT_texture_webp), every size checked first.
#include "scene/gltf/gltf_images.h"

#include <stb_image.h>
#include <tiny_gltf.h>
#include <webp/decode.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>

#include "scene/gltf/gltf_accessors.h"

namespace wf::gltf {
namespace {

bool isPng(const unsigned char* b, size_t n) {
    static const unsigned char magic[8] = {0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a};
    return n >= 8 && std::memcmp(b, magic, 8) == 0;
}

bool isJpeg(const unsigned char* b, size_t n) {
    return n >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff;
}

bool isWebp(const unsigned char* b, size_t n) {
    return n >= 12 && std::memcmp(b, "RIFF", 4) == 0 && std::memcmp(b + 8, "WEBP", 4) == 0;
}

bool sizeAllowed(int width, int height, std::string& why) {
    if (width <= 0 || height <= 0 || unsigned(width) > MAX_TEXTURE_SIDE ||
        unsigned(height) > MAX_TEXTURE_SIDE || size_t(width) * height > MAX_TEXTURE_PIXELS) {
        why = "image of " + std::to_string(width) + "x" + std::to_string(height) +
              " pixels is over the limit of " + std::to_string(MAX_TEXTURE_SIDE) +
              " per side and " + std::to_string(MAX_TEXTURE_PIXELS >> 20) + " Mpixels";
        return false;
    }
    return true;
}

// Decoded RGBA8 rows (R first) into the image.
void copyRgba(const unsigned char* pixels, int width, int height, TextureImage& out) {
    out.width = uint32_t(width);
    out.height = uint32_t(height);
    out.rgba.resize(size_t(width) * size_t(height));
    std::memcpy(out.rgba.data(), pixels, out.rgba.size() * 4);
}

// EXT_texture_webp with Debian's libwebp: the size from the header first, then RGBA8.
bool decodeWebp(const unsigned char* bytes, size_t size, TextureImage& out, std::string& why) {
    int width = 0, height = 0;
    if (!WebPGetInfo(bytes, size, &width, &height)) {
        why = "unreadable WebP header";
        return false;
    }
    if (!sizeAllowed(width, height, why))
        return false;
    int w = 0, h = 0;
    uint8_t* pixels = WebPDecodeRGBA(bytes, size, &w, &h);
    if (!pixels || w != width || h != height) {
        why = pixels ? "WebP image changed size while decoding" : "the WebP data does not decode";
        WebPFree(pixels);
        return false;
    }
    copyRgba(pixels, w, h, out);
    WebPFree(pixels);
    return true;
}

// A 2x2 magenta and black checker, stretched over the surface: a missing image is obvious in
// the render instead of silently white.
TextureImage fallbackChecker() {
    TextureImage image;
    image.width = image.height = 2;
    const uint32_t magenta = 0xffff00ffu, black = 0xff000000u; // ABGR in memory: R first
    image.rgba = {magenta, black, black, magenta};
    image.name = "missing-image checker";
    return image;
}

} // namespace

TextureImage roughnessFromGlossiness(const TextureImage& source, float glossinessFactor) {
    TextureImage out;
    out.width = source.width;
    out.height = source.height;
    out.rgba.resize(source.rgba.size());
    for (size_t i = 0; i < source.rgba.size(); ++i) {
        const float glossiness = glossinessFactor * float(source.rgba[i] >> 24) / 255.0f;
        const uint32_t g = uint32_t(std::lround(255.0f * (1.0f - glossiness)));
        out.rgba[i] = 0xff0000ffu | std::min(g, 255u) << 8; // ABGR: R 1, G roughness, B 0, A 1
    }
    out.name = source.name + " (roughness from glossiness)";
    return out;
}

bool decodeImage(const unsigned char* bytes, size_t size, TextureImage& out, std::string& why) {
    if (isWebp(bytes, size))
        return decodeWebp(bytes, size, out, why);
    if (!isPng(bytes, size) && !isJpeg(bytes, size)) {
        why = "not a PNG, JPEG or WebP image (only those are supported)";
        return false;
    }
    if (size > size_t(INT_MAX)) {
        why = "image data larger than 2 GiB";
        return false;
    }
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(bytes, int(size), &width, &height, &channels)) {
        why = std::string("unreadable image header (") + stbi_failure_reason() + ")";
        return false;
    }
    if (!sizeAllowed(width, height, why))
        return false;
    int w = 0, h = 0, n = 0;
    unsigned char* pixels = stbi_load_from_memory(bytes, int(size), &w, &h, &n, 4);
    if (!pixels || w != width || h != height) { // the header must not change its mind
        why = std::string("cannot decode image (") +
              (pixels ? "size changed" : stbi_failure_reason()) + ")";
        stbi_image_free(pixels);
        return false;
    }
    copyRgba(pixels, w, h, out);
    stbi_image_free(pixels);
    return true;
}

void loadImages(const tinygltf::Model& model, const std::string& file,
                const std::map<int, std::vector<unsigned char>>& encoded, MaterialTables& tables,
                SurfaceData& surface) {
    const uint32_t FAILED = UINT32_MAX;
    std::vector<uint32_t> slot(model.images.size(), FAILED); // glTF image -> surface image
    size_t texelBytes = 0;
    for (size_t i = 0; i < model.images.size(); ++i) {
        if (!tables.imageUsed[i]) {
            continue;
        }
        const tinygltf::Image& image = model.images[i];
        const std::string name = "image " + std::to_string(i) +
                                 (image.uri.empty() || image.uri.size() > 200 ||
                                          image.uri.rfind("data:", 0) == 0
                                      ? ""
                                      : " (" + image.uri + ")");
        const unsigned char* bytes = nullptr;
        size_t size = 0;
        if (image.bufferView != -1) {
            checkIndex(file, image.bufferView, model.bufferViews.size(), "bufferView", name);
            const tinygltf::BufferView& view = model.bufferViews[image.bufferView];
            checkIndex(file, view.buffer, model.buffers.size(), "buffer",
                       "bufferView " + std::to_string(image.bufferView));
            const size_t bufferSize = model.buffers[view.buffer].data.size();
            if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength) {
                fail(file, name + ": bufferView " + std::to_string(image.bufferView) +
                               " extends past the end of buffer " + std::to_string(view.buffer));
            }
            bytes = model.buffers[view.buffer].data.data() + view.byteOffset;
            size = view.byteLength;
        } else if (auto found = encoded.find(int(i)); found != encoded.end()) {
            bytes = found->second.data();
            size = found->second.size();
        }
        TextureImage decoded;
        std::string why = "its file could not be read";
        if (bytes && decodeImage(bytes, size, decoded, why)) {
            texelBytes += decoded.rgba.size() * 4;
            if (texelBytes > MAX_TOTAL_TEXEL_BYTES) {
                why = "the images together exceed " +
                      std::to_string(MAX_TOTAL_TEXEL_BYTES >> 20) + " MiB of texels";
            } else {
                decoded.name = name;
                slot[i] = uint32_t(surface.images.size());
                surface.images.push_back(std::move(decoded));
                continue;
            }
        }
        warn(file, name + " is not used: " + why + " (base colours show a magenta checker)");
    }

    // KHR_materials_pbrSpecularGlossiness: roughness images made from decoded ones.
    std::vector<uint32_t> derivedSlot(tables.derived.size(), FAILED);
    for (size_t d = 0; d < tables.derived.size(); ++d) {
        const uint32_t source = slot[tables.derived[d].image];
        if (source == FAILED)
            continue;
        TextureImage made =
            roughnessFromGlossiness(surface.images[source], tables.derived[d].glossinessFactor);
        texelBytes += made.rgba.size() * 4;
        if (texelBytes > MAX_TOTAL_TEXEL_BYTES) {
            warn(file, made.name + " is not made: the images together exceed " +
                           std::to_string(MAX_TOTAL_TEXEL_BYTES >> 20) +
                           " MiB of texels (its glossiness counts as 1)");
            continue;
        }
        derivedSlot[d] = uint32_t(surface.images.size());
        surface.images.push_back(std::move(made));
    }

    // Each material's broken texture uses: a base colour shows the checker, others are dropped.
    uint32_t checker = FAILED;
    std::vector<uint32_t> refImage(tables.refs.size(), FAILED);
    for (size_t r = 0; r < tables.refs.size(); ++r) {
        const int32_t d = r < tables.refDerived.size() ? tables.refDerived[r] : -1;
        refImage[r] = d >= 0 ? derivedSlot[size_t(d)] : slot[tables.refImage[r]];
    }
    for (Material& m : tables.materials) {
        // A missing glossiness texture reads as 1 (glTF's rule for an absent texture).
        if (m.metallicRoughnessTexture != WF_NO_TEXTURE &&
            refImage[m.metallicRoughnessTexture] == FAILED &&
            tables.refDerived[m.metallicRoughnessTexture] >= 0)
            m.roughness =
                1.0f - tables.derived[size_t(tables.refDerived[m.metallicRoughnessTexture])]
                           .glossinessFactor;
        for (uint32_t* field : textureFields(m)) {
            if (field != &m.baseColorTexture && *field != WF_NO_TEXTURE &&
                refImage[*field] == FAILED) {
                *field = WF_NO_TEXTURE;
            }
        }
        if (m.baseColorTexture != WF_NO_TEXTURE && refImage[m.baseColorTexture] == FAILED) {
            if (checker == FAILED) {
                checker = uint32_t(surface.images.size());
                surface.images.push_back(fallbackChecker());
            }
            refImage[m.baseColorTexture] = checker;
        }
    }
    surface.textureRefs = tables.refs;
    surface.refImage = refImage; // refs no material uses may keep FAILED: never read
}

} // namespace wf::gltf
