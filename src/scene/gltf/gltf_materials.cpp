// Materials and their texture references. Values outside glTF's ranges are refused (an albedo
// above 1 would create energy); extensions the renderer cannot honour are named once.
#include "scene/gltf/gltf_materials.h"

#include <tiny_gltf.h>

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/gltf/gltf_accessors.h"

namespace wf::gltf {
namespace {

const std::set<std::string> SUPPORTED_EXTENSIONS = {
    "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_transmission",
    "KHR_materials_specular", "KHR_materials_clearcoat", "KHR_materials_sheen",
    "KHR_materials_volume", "KHR_materials_iridescence", "KHR_texture_transform", "KHR_lights_punctual",
    "KHR_mesh_quantization", "KHR_draco_mesh_compression", "EXT_meshopt_compression",
    "KHR_meshopt_compression", "KHR_materials_unlit", "EXT_texture_webp",
    "EXT_mesh_gpu_instancing", "KHR_materials_pbrSpecularGlossiness"};

double number(const tinygltf::Value& object, const char* key, double fallback) {
    if (!object.IsObject() || !object.Has(key)) {
        return fallback;
    }
    const tinygltf::Value& value = object.Get(key);
    return value.IsNumber() ? value.GetNumberAsDouble() : std::nan("");
}

// A JSON array of `n` numbers, or `fallback` when the key is absent.
std::vector<double> numbers(const tinygltf::Value& object, const char* key, size_t n,
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

const tinygltf::Value& extension(const tinygltf::ExtensionMap& map, const char* name) {
    static const tinygltf::Value none;
    auto found = map.find(name);
    return found == map.end() ? none : found->second;
}

// The `extensions` object of a textureInfo inside an extension, as tinygltf's map.
tinygltf::ExtensionMap extensionsOf(const tinygltf::Value& info) {
    tinygltf::ExtensionMap out;
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

class MaterialConverter {
public:
    MaterialConverter(const tinygltf::Model& model, const std::string& file)
        : model_(model), file_(file) {
        tables_.imageUsed.assign(model.images.size(), false);
    }
    MaterialTables run();

private:
    uint32_t textureRef(int texture, int texCoord, const tinygltf::ExtensionMap& extensions,
                        bool srgb, const std::string& slot, MaterialNeeds& needs);
    void checkRange(const std::string& name, const char* what, double value, double lo,
                    double hi) const {
        if (!(value >= lo && value <= hi)) { // NaN fails too
            auto text = [](double x) { // %g: "1e+30", not thirty digits of float noise
                char out[32];
                std::snprintf(out, sizeof out, "%g", x);
                return std::string(out);
            };
            fail(file_, name + ": " + what + " must lie in [" + text(lo) + ", " + text(hi) +
                            "] (it is " + text(value) + ")");
        }
    }
    uint32_t extensionTexture(const tinygltf::Value& extension, const char* key, bool srgb,
                              const std::string& name, MaterialNeeds& needs,
                              bool transform = false);
    void convertSpecularGlossiness(const tinygltf::Value& sg, const std::string& name,
                                   Material& out, MaterialNeeds& needs);
    void ignoreTextures(const tinygltf::Value& extension, std::initializer_list<const char*> keys,
                        const std::string& name) const;
    void convertLayers(const tinygltf::Material& m, const std::string& name, Material& out);
    void convertIridescence(const tinygltf::Material& m, const std::string& name, Material& out,
                            MaterialNeeds& needs);
    Material convert(const tinygltf::Material& m, const std::string& name, MaterialNeeds& needs);
    void makeUnlit(Material& out) const;

    const tinygltf::Model& model_;
    const std::string& file_;
    MaterialTables tables_;
};

uint32_t MaterialConverter::textureRef(int texture, int texCoord,
                                       const tinygltf::ExtensionMap& extensions, bool srgb,
                                       const std::string& slot, MaterialNeeds& needs) {
    if (texture == -1) {
        return WF_NO_TEXTURE;
    }
    checkIndex(file_, texture, model_.textures.size(), "texture", slot);
    const tinygltf::Texture& t = model_.textures[texture];
    const std::string textureName = "texture " + std::to_string(texture);
    // EXT_texture_webp names its WebP image in the extension; `source`, when present, is the
    // fallback for viewers without WebP, which this one does not need.
    int source = t.source;
    const tinygltf::Value& webp = extension(t.extensions, "EXT_texture_webp");
    if (webp.IsObject() && webp.Has("source")) {
        const double index = number(webp, "source", -1.0);
        if (!(index >= 0.0 && index < double(model_.images.size())))
            fail(file_, textureName + ": EXT_texture_webp source must name one of the " +
                            std::to_string(model_.images.size()) + " images");
        source = int(index);
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
    const tinygltf::Value& transform = extension(extensions, "KHR_texture_transform");
    if (transform.IsObject()) {
        const std::vector<double> offset = numbers(transform, "offset", 2, {0.0, 0.0});
        const std::vector<double> scale = numbers(transform, "scale", 2, {1.0, 1.0});
        const double rotation = number(transform, "rotation", 0.0);
        const double set = number(transform, "texCoord", texCoord);
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

// A textureInfo inside a material extension (tinygltf parses only the core ones); with
// `transform`, its own KHR_texture_transform is read too.
uint32_t MaterialConverter::extensionTexture(const tinygltf::Value& extension, const char* key,
                                             bool srgb, const std::string& name,
                                             MaterialNeeds& needs, bool transform) {
    if (!extension.IsObject() || !extension.Has(key)) {
        return WF_NO_TEXTURE;
    }
    const tinygltf::Value& info = extension.Get(key);
    const double index = number(info, "index", -1.0);
    if (!(index >= 0.0 && index < 2147483647.0)) {
        fail(file_, name + ": " + key + " needs a texture index");
    }
    const double set = number(info, "texCoord", 0.0);
    const int texCoord = std::isfinite(set) ? int(std::clamp(set, -1.0, 1e6)) : -1;
    return textureRef(int(index), texCoord, transform ? extensionsOf(info) : tinygltf::ExtensionMap{},
                      srgb, name + " " + key, needs);
}

// KHR_materials_pbrSpecularGlossiness (archived; it takes precedence over
// pbrMetallicRoughness, which is then only a fallback and is not read), onto the same BSDF:
//   metallic 0, baseColor = diffuseFactor x diffuseTexture (alpha too),
//   F0 = specularFactor x specularGlossinessTexture.rgb (sRGB), as KHR_materials_specular with
//     specular 1, ior 1.5 and specularColor = specular / F0(1.5), so that
//     min(F0(1.5) specularColor, 1) = the specular colour (F0(1.5) formed in float as
//     bsdfLobes forms it),
//   roughness = 1 - glossinessFactor x specularGlossinessTexture.a: the texture becomes a
//     metallic-roughness one made at load (RoughnessFromGlossiness) with roughness factor 1.
// The spec's diffuse (1 - max(specular)) weight is the BSDF's own energy-conserving coupling
// here (docs/gltf.md).
void MaterialConverter::convertSpecularGlossiness(const tinygltf::Value& sg,
                                                  const std::string& name, Material& out,
                                                  MaterialNeeds& needs) {
    const std::vector<double> diffuse = numbers(sg, "diffuseFactor", 4, {1, 1, 1, 1});
    const std::vector<double> specular = numbers(sg, "specularFactor", 3, {1, 1, 1});
    const double glossiness = number(sg, "glossinessFactor", 1.0);
    for (int c = 0; c < 4; ++c) {
        checkRange(name, "diffuseFactor", diffuse[c], 0.0, 1.0);
        out.baseColor[c] = float(diffuse[c]);
    }
    checkRange(name, "glossinessFactor", glossiness, 0.0, 1.0);
    out.metallic = 0.0f;
    out.roughness = float(1.0 - glossiness);
    out.ior = 1.5f;
    out.specular = 1.0f;
    const float r = (out.ior - 1.0f) / (out.ior + 1.0f);
    const float f0 = r * r; // 0.04, formed as bsdfLobes forms it
    for (int c = 0; c < 3; ++c) {
        checkRange(name, "specularFactor", specular[c], 0.0, 1.0);
        out.specularColor[c] = float(specular[c] / double(f0));
    }
    out.baseColorTexture = extensionTexture(sg, "diffuseTexture", true, name, needs, true);
    out.specularColorTexture =
        extensionTexture(sg, "specularGlossinessTexture", true, name, needs, true);
    if (out.specularColorTexture == WF_NO_TEXTURE)
        return;
    // The same reference, read as data from the image made at load.
    const uint32_t source = tables_.refImage[out.specularColorTexture];
    const float factor = float(glossiness);
    int32_t made = -1;
    for (size_t d = 0; d < tables_.derived.size(); ++d)
        if (tables_.derived[d].image == source && tables_.derived[d].glossinessFactor == factor)
            made = int32_t(d);
    if (made < 0) {
        made = int32_t(tables_.derived.size());
        tables_.derived.push_back({source, factor});
    }
    TextureRef ref = tables_.refs[out.specularColorTexture];
    ref.flags &= ~WF_TEXTURE_SRGB;
    tables_.refs.push_back(ref);
    tables_.refImage.push_back(source);
    tables_.refDerived.push_back(made);
    out.metallicRoughnessTexture = uint32_t(tables_.refs.size() - 1);
    out.roughness = 1.0f;
}

void MaterialConverter::ignoreTextures(const tinygltf::Value& extension,
                                       std::initializer_list<const char*> keys,
                                       const std::string& name) const {
    for (const char* key : keys) {
        if (extension.IsObject() && extension.Has(key)) {
            warn(file_, name + ": " + key + " is not supported and is ignored (its factor is "
                                            "used)");
        }
    }
}

// KHR_materials_clearcoat, _sheen and _volume: factors only (their textures are ignored).
void MaterialConverter::convertLayers(const tinygltf::Material& m, const std::string& name,
                                      Material& out) {
    const tinygltf::Value& coat = extension(m.extensions, "KHR_materials_clearcoat");
    out.clearcoat = float(number(coat, "clearcoatFactor", 0.0));
    out.clearcoatRoughness = float(number(coat, "clearcoatRoughnessFactor", 0.0));
    checkRange(name, "clearcoatFactor", out.clearcoat, 0.0, 1.0);
    checkRange(name, "clearcoatRoughnessFactor", out.clearcoatRoughness, 0.0, 1.0);
    ignoreTextures(coat,
                   {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"},
                   name);

    const tinygltf::Value& sheen = extension(m.extensions, "KHR_materials_sheen");
    const std::vector<double> sheenColor = numbers(sheen, "sheenColorFactor", 3, {0, 0, 0});
    for (int c = 0; c < 3; ++c) {
        checkRange(name, "sheenColorFactor", sheenColor[c], 0.0, 1.0);
        out.sheenColor[c] = float(sheenColor[c]);
    }
    out.sheenRoughness = float(number(sheen, "sheenRoughnessFactor", 0.0));
    checkRange(name, "sheenRoughnessFactor", out.sheenRoughness, 0.0, 1.0);
    ignoreTextures(sheen, {"sheenColorTexture", "sheenRoughnessTexture"}, name);

    const tinygltf::Value& volume = extension(m.extensions, "KHR_materials_volume");
    out.thickness = float(number(volume, "thicknessFactor", 0.0));
    checkRange(name, "thicknessFactor", out.thickness, 0.0, 1e30);
    const double distance = number(volume, "attenuationDistance", INFINITY);
    if (!(distance > 0.0)) { // NaN fails too; +inf (the default) means no attenuation
        fail(file_, name + ": attenuationDistance must be > 0");
    }
    const std::vector<double> color = numbers(volume, "attenuationColor", 3, {1, 1, 1});
    for (int c = 0; c < 3; ++c) {
        checkRange(name, "attenuationColor", color[c], 0.0, 1.0);
        // sigma_a = -ln(color) / distance, kept finite (black absorbs everything within 1e-30).
        const double sigma = -std::log(std::max(color[c], 1e-30)) / distance;
        out.attenuation[c] = float(std::min(sigma, 1e30));
    }
    ignoreTextures(volume, {"thicknessTexture"}, name);
}

// KHR_materials_iridescence: a thin film over the dielectric and metal Fresnel (iridescence.h).
void MaterialConverter::convertIridescence(const tinygltf::Material& m, const std::string& name,
                                           Material& out, MaterialNeeds& needs) {
    const tinygltf::Value& film = extension(m.extensions, "KHR_materials_iridescence");
    if (!film.IsObject()) {
        return;
    }
    const double factor = number(film, "iridescenceFactor", 0.0);
    const double ior = number(film, "iridescenceIor", 1.3);
    const double minimum = number(film, "iridescenceThicknessMinimum", 100.0);
    const double maximum = number(film, "iridescenceThicknessMaximum", 400.0);
    checkRange(name, "iridescenceFactor", factor, 0.0, 1.0);
    if (!(ior >= 1.0 && ior <= 10.0)) { // NaN fails too
        fail(file_, name + ": iridescenceIor must lie in [1, 10]");
    }
    checkRange(name, "iridescenceThicknessMinimum", minimum, 0.0, 1e6);
    checkRange(name, "iridescenceThicknessMaximum", maximum, 0.0, 1e6);
    out.iridescence = float(factor);
    out.iridescenceIor = float(ior);
    out.iridescenceThicknessMinimum = float(minimum);
    out.iridescenceThicknessMaximum = float(maximum);
    out.iridescenceTexture =
        extensionTexture(film, "iridescenceTexture", false, name, needs, true);
    out.iridescenceThicknessTexture =
        extensionTexture(film, "iridescenceThicknessTexture", false, name, needs, true);
}

Material MaterialConverter::convert(const tinygltf::Material& m, const std::string& name,
                                    MaterialNeeds& needs) {
    const auto& pbr = m.pbrMetallicRoughness;
    Material out = defaultMaterial();
    const tinygltf::Value& specGloss =
        extension(m.extensions, "KHR_materials_pbrSpecularGlossiness");
    const bool metallicRoughness = !specGloss.IsObject(); // else only the fallback: unread
    if (m.emissiveFactor.size() != 3 ||
        (metallicRoughness && pbr.baseColorFactor.size() != 4)) {
        fail(file_, name + ": baseColorFactor needs 4 numbers and emissiveFactor 3");
    }
    if (metallicRoughness) {
        for (int c = 0; c < 4; ++c) {
            checkRange(name, "baseColorFactor", pbr.baseColorFactor[c], 0.0, 1.0);
            out.baseColor[c] = float(pbr.baseColorFactor[c]);
        }
        checkRange(name, "metallicFactor", pbr.metallicFactor, 0.0, 1.0);
        checkRange(name, "roughnessFactor", pbr.roughnessFactor, 0.0, 1.0);
        out.metallic = float(pbr.metallicFactor);
        out.roughness = float(pbr.roughnessFactor);
    }
    out.specular = 1.0f; // the glTF BRDF's dielectric layer, unless KHR_materials_specular
    const double strength =
        number(extension(m.extensions, "KHR_materials_emissive_strength"), "emissiveStrength", 1);
    for (int c = 0; c < 3; ++c) {
        out.emission[c] = float(m.emissiveFactor[c] * strength);
        if (!(m.emissiveFactor[c] >= 0.0 && strength >= 0.0 && std::isfinite(out.emission[c]))) {
            fail(file_, name + ": emissiveFactor and emissiveStrength must be finite and >= 0");
        }
    }
    out.flags = m.doubleSided ? WF_MATERIAL_DOUBLE_SIDED : 0u;
    if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
        checkRange(name, "alphaCutoff", m.alphaCutoff, 0.0, 1e30);
        out.alphaCutoff = float(m.alphaCutoff);
        out.flags |= m.alphaMode == "MASK" ? WF_MATERIAL_ALPHA_MASK : WF_MATERIAL_ALPHA_BLEND;
    } else if (m.alphaMode != "OPAQUE") {
        fail(file_, name + ": alphaMode must be OPAQUE, MASK or BLEND");
    }
    const tinygltf::Value& ior = extension(m.extensions, "KHR_materials_ior");
    out.ior = float(number(ior, "ior", 1.5));
    if (!(out.ior >= 1.0f && out.ior <= 10.0f)) {
        warn(file_, name + ": KHR_materials_ior ior must lie in [1, 10]; using 1.5");
        out.ior = 1.5f;
    }
    const tinygltf::Value& transmission = extension(m.extensions, "KHR_materials_transmission");
    out.transmission = float(number(transmission, "transmissionFactor", 0.0));
    checkRange(name, "transmissionFactor", out.transmission, 0.0, 1.0);
    const tinygltf::Value& specular = extension(m.extensions, "KHR_materials_specular");
    if (!metallicRoughness) {
        // The specular-glossiness model sets F0 itself; the spec forbids _ior and _specular
        // beside it.
        for (const char* other : {"KHR_materials_ior", "KHR_materials_specular"})
            if (extension(m.extensions, other).IsObject())
                warn(file_, name + ": " + other + " is ignored beside "
                                   "KHR_materials_pbrSpecularGlossiness");
    } else if (specular.IsObject()) {
        out.specular = float(number(specular, "specularFactor", 1.0));
        checkRange(name, "specularFactor", out.specular, 0.0, 1.0);
        const std::vector<double> color = numbers(specular, "specularColorFactor", 3, {1, 1, 1});
        for (int c = 0; c < 3; ++c) {
            checkRange(name, "specularColorFactor", color[c], 0.0, 1e30);
            out.specularColor[c] = float(color[c]);
        }
    }
    convertLayers(m, name, out);
    checkRange(name, "normalTexture.scale", m.normalTexture.scale, -1e30, 1e30);
    out.normalScale = float(m.normalTexture.scale);

    const auto& base = pbr.baseColorTexture;
    const auto& mr = pbr.metallicRoughnessTexture;
    const auto& normal = m.normalTexture;
    const auto& emissive = m.emissiveTexture;
    if (metallicRoughness) {
        out.baseColorTexture = textureRef(base.index, base.texCoord, base.extensions, true,
                                          name + " baseColorTexture", needs);
        out.metallicRoughnessTexture = textureRef(mr.index, mr.texCoord, mr.extensions, false,
                                                  name + " metallicRoughnessTexture", needs);
    }
    out.normalTexture = textureRef(normal.index, normal.texCoord, normal.extensions, false,
                                   name + " normalTexture", needs);
    out.emissiveTexture = textureRef(emissive.index, emissive.texCoord, emissive.extensions,
                                     true, name + " emissiveTexture", needs);
    if (transmission.IsObject() && transmission.Has("transmissionTexture")) {
        const tinygltf::Value& info = transmission.Get("transmissionTexture");
        const double index = number(info, "index", -1.0);
        if (!(index >= 0.0 && index < 2147483647.0)) {
            fail(file_, name + ": transmissionTexture needs a texture index");
        }
        const double set = number(info, "texCoord", 0.0);
        const int texCoord = std::isfinite(set) ? int(std::clamp(set, -1.0, 1e6)) : -1;
        out.transmissionTexture =
            textureRef(int(index), texCoord, {}, false, name + " transmissionTexture", needs);
    }
    if (!metallicRoughness) {
        convertSpecularGlossiness(specGloss, name, out, needs);
    } else if (specular.IsObject()) {
        out.specularTexture = extensionTexture(specular, "specularTexture", false, name, needs);
        out.specularColorTexture =
            extensionTexture(specular, "specularColorTexture", true, name, needs);
    }
    convertIridescence(m, name, out, needs);
    if (out.normalTexture != WF_NO_TEXTURE) {
        const TextureRef& ref = tables_.refs[out.normalTexture];
        needs.normalMapTexCoord = (ref.flags & WF_TEXTURE_TEXCOORD1) ? 1 : 0;
    }
    if (extension(m.extensions, "KHR_materials_unlit").IsObject())
        makeUnlit(out);
    return out;
}

// KHR_materials_unlit: the surface shows its base colour whatever lights it. A path tracer has
// that as emission (base colour factor x texture, sRGB-decoded, front faces unless
// doubleSided) over a black, non-reflecting surface; the base colour texture stays for its
// alpha. Like any emitter, it also lights what it faces.
void MaterialConverter::makeUnlit(Material& out) const {
    out.emission = glm::vec3(out.baseColor);
    out.emissiveTexture = out.baseColorTexture;
    out.baseColor = glm::vec4(0.0f, 0.0f, 0.0f, out.baseColor.w);
    out.metallic = 0.0f;
    out.specular = 0.0f; // exact Lambert of a black base: no reflection at all
    out.transmission = 0.0f;
    out.transmissionTexture = out.specularTexture = out.specularColorTexture =
        out.metallicRoughnessTexture = out.normalTexture = WF_NO_TEXTURE;
    out.clearcoat = 0.0f;
    out.sheenColor = glm::vec3(0.0f);
    out.iridescence = 0.0f;
    out.iridescenceTexture = out.iridescenceThicknessTexture = WF_NO_TEXTURE;
}

MaterialTables MaterialConverter::run() {
    tables_.materials.reserve(model_.materials.size());
    for (size_t i = 0; i < model_.materials.size(); ++i) {
        MaterialNeeds needs;
        tables_.materials.push_back(
            convert(model_.materials[i], "material " + std::to_string(i), needs));
        tables_.needs.push_back(needs);
    }
    return std::move(tables_);
}

} // namespace

// KHR_materials_variants is read by gltf_variants, before the materials.
bool isSupportedExtension(const std::string& name) {
    return SUPPORTED_EXTENSIONS.count(name) || name == "KHR_materials_variants";
}

Material defaultMaterial() {
    Material m{};
    m.baseColor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
    m.metallic = 0.0f;
    m.roughness = 1.0f;
    m.ior = 1.5f;
    m.specular = 0.0f; // exact Lambert, as README promises for primitives without a material
    m.specularColor = glm::vec3(1.0f);
    m.alphaCutoff = 0.5f;
    m.normalScale = 1.0f;
    m.baseColorTexture = m.metallicRoughnessTexture = m.normalTexture = m.emissiveTexture =
        m.transmissionTexture = m.specularTexture = m.specularColorTexture = WF_NO_TEXTURE;
    m.attenuation = glm::vec3(0.0f); // no clearcoat, sheen or absorption: all zero
    m.iridescence = 0.0f; // no thin film; the extension's defaults otherwise
    m.iridescenceIor = 1.3f;
    m.iridescenceThicknessMinimum = 100.0f;
    m.iridescenceThicknessMaximum = 400.0f;
    m.iridescenceTexture = m.iridescenceThicknessTexture = WF_NO_TEXTURE;
    return m;
}

MaterialTables convertMaterials(const tinygltf::Model& model, const std::string& file) {
    return MaterialConverter(model, file).run();
}

} // namespace wf::gltf
