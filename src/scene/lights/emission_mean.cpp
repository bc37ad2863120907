#include "scene/lights/emission_mean.h"

#include <algorithm>
#include <cmath>

namespace wf {
namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

int wrap(int i, int n, uint32_t mode) {
    if (mode == WF_WRAP_CLAMP)
        return std::clamp(i, 0, n - 1);
    if (mode == WF_WRAP_MIRROR) {
        const int m = ((i % (2 * n)) + 2 * n) % (2 * n);
        return std::clamp(m < n ? m : 2 * n - 1 - m, 0, n - 1);
    }
    return std::clamp(((i % n) + n) % n, 0, n - 1);
}

// Texel (nearest) of the image at the file's uv, as textures.glsl addresses it.
glm::vec3 texelAt(const TextureImage& image, const TextureRef& ref, glm::vec2 uvFile) {
    const glm::vec3 h(uvFile, 1.0f);
    glm::vec2 uv(glm::dot(ref.uRow, h), glm::dot(ref.vRow, h));
    uv -= glm::floor(uv / 2.0f) * 2.0f; // two periods hold every wrap mode's pattern
    const int x = wrap(int(std::floor(uv.x * image.width)), int(image.width), ref.flags & 3u);
    const int y = wrap(int(std::floor(uv.y * image.height)), int(image.height), (ref.flags >> 2) & 3u);
    const uint32_t rgba = image.rgba[size_t(y) * image.width + x];
    glm::vec3 c(float(rgba & 0xffu), float((rgba >> 8) & 0xffu), float((rgba >> 16) & 0xffu));
    c /= 255.0f;
    if (ref.flags & WF_TEXTURE_SRGB)
        c = glm::vec3(srgbToLinear(c.x), srgbToLinear(c.y), srgbToLinear(c.z));
    return c;
}

} // namespace

glm::vec3 meanEmissiveTexture(const SurfaceData& surface, uint32_t ref, uint32_t triangle) {
    // Scenes built in code leave the texture fields 0 with no textures: the factor alone.
    if (ref >= surface.textureRefs.size() || ref >= surface.refImage.size() ||
        surface.refImage[ref] >= surface.images.size())
        return glm::vec3(1.0f);
    const TextureRef& texture = surface.textureRefs[ref];
    const TextureImage& image = surface.images[surface.refImage[ref]];
    const auto& layer = (texture.flags & WF_TEXTURE_TEXCOORD1) ? surface.uv1 : surface.uv0;
    const glm::vec3 floor(1.0f / 1024.0f);
    if (image.width == 0 || image.height == 0 || triangle >= layer.size())
        return glm::vec3(1.0f);
    const TriangleUvs& uvs = layer[triangle];
    // The footprint in texels decides the sample count: a k x k grid of the unit square,
    // folded onto the triangle (Heitz's mapping keeps the cells' areas equal).
    const glm::vec2 e1 = (uvs.uv1 - uvs.uv0) * glm::vec2(image.width, image.height);
    const glm::vec2 e2 = (uvs.uv2 - uvs.uv0) * glm::vec2(image.width, image.height);
    const double texels = 0.5 * std::abs(double(e1.x) * e2.y - double(e1.y) * e2.x);
    const int k = std::clamp(int(std::ceil(std::sqrt(std::min(texels, 1024.0)))), 2, 32);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const float u0 = (i + 0.5f) / k, u1 = (j + 0.5f) / k;
            float b1, b2;
            if (u0 < u1) {
                b1 = u0 * 0.5f;
                b2 = u1 - b1;
            } else {
                b2 = u1 * 0.5f;
                b1 = u0 - b2;
            }
            const glm::vec2 uv = (1.0f - b1 - b2) * uvs.uv0 + b1 * uvs.uv1 + b2 * uvs.uv2;
            sum += glm::dvec3(texelAt(image, texture, uv));
        }
    return glm::max(glm::vec3(sum / double(k * k)), floor);
}

} // namespace wf
