// Texture references: which image a texture use reads, and how (see the header).
#include "scene/gltf/gltf_texture_refs.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>

#include "scene/gltf/gltf_accessors.h"

namespace wf::gltf {
namespace {

// The `extensions` object of a textureInfo inside an extension, as tinygltf's map.
ExtensionObjects extensionsOf(const tinygltf::Value& info) {
    ExtensionObjects out;
    if (info.IsObject() && info.Has("extensions") && info.Get("extensions").IsObject()) {
        const tinygltf::Value& all = info.Get("extensions");
        for (const std::string& key : all.Keys())
            out[key] = all.Get(key);
    }
    return out;
}

uint32_t wrapMode(int gl) {
    switch (gl) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return WF_WRAP_CLAMP;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return WF_WRAP_MIRROR;
    default: return WF_WRAP_REPEAT;
    }
}

} // namespace

double jsonNumber(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) {
        return fallback;
    }
    const tinygltf::Value& value = object.Get(key);
    return value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
}

std::vector<double> jsonNumbers(const tinygltf::Value& object, const char* key, size_t n,
                                std::vector<double> fallback) {
    if (!object.IsObject() || !object.Has(key)) {
        return fallback;
    }
    const tinygltf::Value& value = object.Get(key);
    std::vector<double> out(n, std::nan(""));
    if (value.IsArray() && value.ArrayLen() == n) {
        for (size_t i = 0; i < n; ++i) {
            const tinygltf::Value& item = value.Get(int(i));
            out[i] = item.IsNumber() ? item.GetNumberAsDouble() : std::nan("");
        }
    }
    return out;
}

const tinygltf::Value& extensionIn(const ExtensionObjects& map, const char* name) {
    static const tinygltf::Value none;
    auto found = map.find(name);
    return found == map.end() ? none : found->second;
}

bool isReadThroughFallbacks(const std::string& extension) {
    return extension == "KHR_texture_basisu";
}

uint32_t TextureRefs::core(int texture, int texCoord, const ExtensionObjects& extensions,
                           bool srgb, const std::string& slot, MaterialNeeds& needs) {
    if (texture == -1) {
        return WF_NO_TEXTURE;
    }
    checkIndex(file_, texture, model_.textures.size(), "texture", slot);
    const tinygltf::Texture& t = model_.textures[texture];
    const std::string textureName = "texture " + std::to_string(texture);
    // EXT_texture_webp names its WebP image in the extension; `source`, when present, is the
    // fallback for viewers without WebP, which this one does not need.
    int source = t.source;
    const tinygltf::Value& webp = extensionIn(t.extensions, "EXT_texture_webp");
    if (webp.IsObject() && webp.Has("source")) {
        const double index = jsonNumber(webp, "source", -1.0);
        if (!(index >= 0.0 && index < double(model_.images.size())))
            fail(file_, textureName + ": EXT_texture_webp source must name one of the " +
                            std::to_string(model_.images.size()) + " images");
        source = int(index);
    }
    // KHR_texture_basisu: Debian 12 has no Basis Universal (KTX2) decoder, so `source`, the
    // PNG/JPEG/WebP fallback, is read and the KTX2 image never; without a fallback the
    // texture is dropped, with one warning for the file.
    if (source == -1 && extensionIn(t.extensions, "KHR_texture_basisu").IsObject()) {
        if (!basisuWarned_)
            warn(file_, textureName + " (" + slot + ") is KHR_texture_basisu (KTX2) only, "
                        "which is not decoded here: it and any other texture without a PNG, "
                        "JPEG or WebP source are ignored");
        basisuWarned_ = true;
        return WF_NO_TEXTURE;
    }
    if (source == -1) {
        warn(file_, textureName + " has no image source; " + slot + " is ignored");
        return WF_NO_TEXTURE;
    }
    checkIndex(file_, source, model_.images.size(), "image", textureName);
    TextureRef ref{};
    ref.uRow = glm::vec3(1, 0, 0);
    ref.vRow = glm::vec3(0, 1, 0);
    uint32_t wrapS = WF_WRAP_REPEAT, wrapT = WF_WRAP_REPEAT;
    if (t.sampler != -1) {
        checkIndex(file_, t.sampler, model_.samplers.size(), "sampler", textureName);
        const tinygltf::Sampler& sampler = model_.samplers[t.sampler];
        wrapS = wrapMode(sampler.wrapS);
        wrapT = wrapMode(sampler.wrapT);
        ref.flags |= sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST ? WF_TEXTURE_NEAREST : 0u;
    }
    ref.flags |= wrapS | wrapT << 2 | (srgb ? WF_TEXTURE_SRGB : 0u);
    // KHR_texture_transform: uv' = T * R * S * uv, and it may override the UV set.
    const tinygltf::Value& transform = extensionIn(extensions, "KHR_texture_transform");
    if (transform.IsObject()) {
        const std::vector<double> offset = jsonNumbers(transform, "offset", 2, {0.0, 0.0});
        const std::vector<double> scale = jsonNumbers(transform, "scale", 2, {1.0, 1.0});
        const double rotation = jsonNumber(transform, "rotation", 0.0);
        const double set = jsonNumber(transform, "texCoord", texCoord);
        texCoord = std::isfinite(set) ? int(std::clamp(set, -1.0, 1e6)) : -1;
        const double c = std::cos(rotation), s = std::sin(rotation);
        ref.uRow = glm::vec3(float(c * scale[0]), float(s * scale[1]), float(offset[0]));
        ref.vRow = glm::vec3(float(-s * scale[0]), float(c * scale[1]), float(offset[1]));
        const glm::vec3 sum = ref.uRow + ref.vRow;
        if (!std::isfinite(sum.x + sum.y + sum.z)) {
            fail(file_, slot + ": KHR_texture_transform needs finite numbers");
        }
    }
    if (texCoord < 0 || texCoord > 1) {
        warn(file_, slot + " uses TEXCOORD_" + std::to_string(texCoord) +
                        "; only TEXCOORD_0 and TEXCOORD_1 are supported, using TEXCOORD_0");
        texCoord = 0;
    }
    ref.flags |= texCoord == 1 ? WF_TEXTURE_TEXCOORD1 : 0u;
    (texCoord == 1 ? needs.uv1 : needs.uv0) = true;
    tables_.imageUsed[source] = true;
    tables_.refs.push_back(ref);
    tables_.refImage.push_back(uint32_t(source));
    tables_.refDerived.push_back(-1);
    return uint32_t(tables_.refs.size() - 1);
}

// tinygltf parses only the core textureInfos; these are read from the extension's JSON.
uint32_t TextureRefs::inExtension(const tinygltf::Value& extension, const char* key, bool srgb,
                                  const std::string& material, MaterialNeeds& needs,
                                  float* scale) {
    if (!extension.IsObject() || !extension.Has(key)) {
        return WF_NO_TEXTURE;
    }
    const tinygltf::Value& info = extension.Get(key);
    const double index = jsonNumber(info, "index", -1.0);
    if (!(index >= 0.0 && index < 2147483647.0)) {
        fail(file_, material + ": " + key + " needs a texture index");
    }
    if (scale) {
        const double s = jsonNumber(info, "scale", 1.0);
        if (!std::isfinite(s) || std::abs(s) > 1e30)
            fail(file_, material + ": " + key + ".scale must be a finite number");
        *scale = float(s);
    }
    const double set = jsonNumber(info, "texCoord", 0.0);
    const int texCoord = std::isfinite(set) ? int(std::clamp(set, -1.0, 1e6)) : -1;
    return core(int(index), texCoord, extensionsOf(info), srgb, material + " " + key, needs);
}

} // namespace wf::gltf
