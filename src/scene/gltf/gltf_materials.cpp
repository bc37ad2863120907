// Materials and their texture references. Values outside glTF's ranges are refused (an albedo
// above 1 would create energy); extensions the renderer cannot honour are named once.
#include "scene/gltf/gltf_materials.h"

#include <tiny_gltf.h>

#include <cstdio>

#include <algorithm>
#include <cmath>
#include <set>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/gltf_texture_refs.h"

namespace wf::gltf {
namespace {

const std::set<std::string> SUPPORTED_EXTENSIONS = {
    "KHR_materials_emissive_strength", "KHR_materials_ior", "KHR_materials_transmission",
    "KHR_materials_specular", "KHR_materials_clearcoat", "KHR_materials_sheen",
    "KHR_materials_volume", "KHR_materials_iridescence", "KHR_texture_transform", "KHR_lights_punctual",
    "KHR_materials_anisotropy", "KHR_materials_diffuse_transmission", "KHR_materials_dispersion",
    "KHR_mesh_quantization", "KHR_draco_mesh_compression", "EXT_meshopt_compression",
    "KHR_meshopt_compression", "KHR_materials_unlit", "EXT_texture_webp",
    "EXT_mesh_gpu_instancing", "KHR_materials_pbrSpecularGlossiness"};

class MaterialConverter {
public:
    MaterialConverter(const tinygltf::Model& model, const std::string& file)
        : model_(model), file_(file), textures_(model, file, tables_) {
        tables_.imageUsed.assign(model.images.size(), false);
    }
    MaterialTables run();

private:
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
    void convertSpecularGlossiness(const tinygltf::Value& sg, const std::string& name,
                                   Material& out, MaterialNeeds& needs);
    void convertLayers(const tinygltf::Material& m, const std::string& name, Material& out,
                       MaterialNeeds& needs);
    void convertIridescence(const tinygltf::Material& m, const std::string& name, Material& out,
                            MaterialNeeds& needs);
    void convertAnisotropy(const tinygltf::Material& m, const std::string& name, Material& out,
                           MaterialNeeds& needs);
    void convertDiffuseTransmission(const tinygltf::Material& m, const std::string& name,
                                    Material& out, MaterialNeeds& needs);
    Material convert(const tinygltf::Material& m, const std::string& name, MaterialNeeds& needs);
    void makeUnlit(Material& out) const;

    const tinygltf::Model& model_;
    const std::string& file_;
    MaterialTables tables_;
    TextureRefs textures_; // appends to tables_
};

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
    const std::vector<double> diffuse = jsonNumbers(sg, "diffuseFactor", 4, {1, 1, 1, 1});
    const std::vector<double> specular = jsonNumbers(sg, "specularFactor", 3, {1, 1, 1});
    const double glossiness = jsonNumber(sg, "glossinessFactor", 1.0);
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
    out.baseColorTexture = textures_.inExtension(sg, "diffuseTexture", true, name, needs);
    out.specularColorTexture =
        textures_.inExtension(sg, "specularGlossinessTexture", true, name, needs);
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

// KHR_materials_clearcoat, _sheen and _volume: factors, and textures that multiply them (the
// channels the spec names), the coat's own normal map with its scale.
void MaterialConverter::convertLayers(const tinygltf::Material& m, const std::string& name,
                                      Material& out, MaterialNeeds& needs) {
    const tinygltf::Value& coat = extensionIn(m.extensions, "KHR_materials_clearcoat");
    out.clearcoat = float(jsonNumber(coat, "clearcoatFactor", 0.0));
    out.clearcoatRoughness = float(jsonNumber(coat, "clearcoatRoughnessFactor", 0.0));
    checkRange(name, "clearcoatFactor", out.clearcoat, 0.0, 1.0);
    checkRange(name, "clearcoatRoughnessFactor", out.clearcoatRoughness, 0.0, 1.0);
    out.clearcoatTexture = textures_.inExtension(coat, "clearcoatTexture", false, name, needs);
    out.clearcoatRoughnessTexture =
        textures_.inExtension(coat, "clearcoatRoughnessTexture", false, name, needs);
    out.clearcoatNormalTexture = textures_.inExtension(coat, "clearcoatNormalTexture", false,
                                                       name, needs, &out.clearcoatNormalScale);

    const tinygltf::Value& sheen = extensionIn(m.extensions, "KHR_materials_sheen");
    const std::vector<double> sheenColor = jsonNumbers(sheen, "sheenColorFactor", 3, {0, 0, 0});
    for (int c = 0; c < 3; ++c) {
        checkRange(name, "sheenColorFactor", sheenColor[c], 0.0, 1.0);
        out.sheenColor[c] = float(sheenColor[c]);
    }
    out.sheenRoughness = float(jsonNumber(sheen, "sheenRoughnessFactor", 0.0));
    checkRange(name, "sheenRoughnessFactor", out.sheenRoughness, 0.0, 1.0);
    out.sheenColorTexture = textures_.inExtension(sheen, "sheenColorTexture", true, name, needs);
    out.sheenRoughnessTexture =
        textures_.inExtension(sheen, "sheenRoughnessTexture", false, name, needs);

    const tinygltf::Value& volume = extensionIn(m.extensions, "KHR_materials_volume");
    out.thickness = float(jsonNumber(volume, "thicknessFactor", 0.0));
    checkRange(name, "thicknessFactor", out.thickness, 0.0, 1e30);
    const double distance = jsonNumber(volume, "attenuationDistance", INFINITY);
    if (!(distance > 0.0)) { // NaN fails too; +inf (the default) means no attenuation
        fail(file_, name + ": attenuationDistance must be > 0");
    }
    const std::vector<double> color = jsonNumbers(volume, "attenuationColor", 3, {1, 1, 1});
    for (int c = 0; c < 3; ++c) {
        checkRange(name, "attenuationColor", color[c], 0.0, 1.0);
        // sigma_a = -ln(color) / distance, kept finite (black absorbs everything within 1e-30).
        const double sigma = -std::log(std::max(color[c], 1e-30)) / distance;
        out.attenuation[c] = float(std::min(sigma, 1e30));
    }
    out.thicknessTexture = textures_.inExtension(volume, "thicknessTexture", false, name, needs);
}

// KHR_materials_iridescence: a thin film over the dielectric and metal Fresnel (iridescence.h).
void MaterialConverter::convertIridescence(const tinygltf::Material& m, const std::string& name,
                                           Material& out, MaterialNeeds& needs) {
    const tinygltf::Value& film = extensionIn(m.extensions, "KHR_materials_iridescence");
    if (!film.IsObject()) {
        return;
    }
    const double factor = jsonNumber(film, "iridescenceFactor", 0.0);
    const double ior = jsonNumber(film, "iridescenceIor", 1.3);
    const double minimum = jsonNumber(film, "iridescenceThicknessMinimum", 100.0);
    const double maximum = jsonNumber(film, "iridescenceThicknessMaximum", 400.0);
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
        textures_.inExtension(film, "iridescenceTexture", false, name, needs);
    out.iridescenceThicknessTexture =
        textures_.inExtension(film, "iridescenceThicknessTexture", false, name, needs);
}

// KHR_materials_diffuse_transmission: the share of the diffuse base that leaves through the
// other side as a Lambert lobe of its own colour (bsdf.h).
void MaterialConverter::convertDiffuseTransmission(const tinygltf::Material& m,
                                                   const std::string& name, Material& out,
                                                   MaterialNeeds& needs) {
    const tinygltf::Value& dt = extensionIn(m.extensions, "KHR_materials_diffuse_transmission");
    if (!dt.IsObject())
        return;
    const double factor = jsonNumber(dt, "diffuseTransmissionFactor", 0.0);
    checkRange(name, "diffuseTransmissionFactor", factor, 0.0, 1.0);
    out.diffuseTransmission = float(factor);
    const std::vector<double> color =
        jsonNumbers(dt, "diffuseTransmissionColorFactor", 3, {1, 1, 1});
    for (int c = 0; c < 3; ++c) {
        checkRange(name, "diffuseTransmissionColorFactor", color[c], 0.0, 1.0);
        out.diffuseTransmissionColor[c] = float(color[c]);
    }
    out.diffuseTransmissionTexture =
        textures_.inExtension(dt, "diffuseTransmissionTexture", false, name, needs);
    out.diffuseTransmissionColorTexture =
        textures_.inExtension(dt, "diffuseTransmissionColorTexture", true, name, needs);
}

// KHR_materials_anisotropy: GGX stretched along a direction in the tangent frame
// (bsdf/anisotropy.h). Primitives using it get tangent frames as normal-mapped ones do.
void MaterialConverter::convertAnisotropy(const tinygltf::Material& m, const std::string& name,
                                          Material& out, MaterialNeeds& needs) {
    const tinygltf::Value& anisotropy = extensionIn(m.extensions, "KHR_materials_anisotropy");
    if (!anisotropy.IsObject())
        return;
    const double strength = jsonNumber(anisotropy, "anisotropyStrength", 0.0);
    const double rotation = jsonNumber(anisotropy, "anisotropyRotation", 0.0);
    checkRange(name, "anisotropyStrength", strength, 0.0, 1.0);
    if (!std::isfinite(rotation)) // any angle is valid glTF; a string or null is not
        fail(file_, name + ": anisotropyRotation must be a number (radians)");
    out.anisotropyStrength = float(strength);
    out.anisotropyRotation = glm::vec2(float(std::cos(rotation)), float(std::sin(rotation)));
    out.anisotropyTexture =
        textures_.inExtension(anisotropy, "anisotropyTexture", false, name, needs);
    if (out.anisotropyStrength > 0.0f && needs.normalMapTexCoord < 0) {
        const bool uv1 = out.anisotropyTexture != WF_NO_TEXTURE &&
                         (tables_.refs[out.anisotropyTexture].flags & WF_TEXTURE_TEXCOORD1);
        needs.normalMapTexCoord = uv1 ? 1 : 0; // the tangents' UV set (the normal map's wins)
    }
}

Material MaterialConverter::convert(const tinygltf::Material& m, const std::string& name,
                                    MaterialNeeds& needs) {
    const auto& pbr = m.pbrMetallicRoughness;
    Material out = defaultMaterial();
    const tinygltf::Value& specGloss =
        extensionIn(m.extensions, "KHR_materials_pbrSpecularGlossiness");
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
        jsonNumber(extensionIn(m.extensions, "KHR_materials_emissive_strength"), "emissiveStrength", 1);
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
    const tinygltf::Value& ior = extensionIn(m.extensions, "KHR_materials_ior");
    out.ior = float(jsonNumber(ior, "ior", 1.5));
    if (!(out.ior >= 1.0f && out.ior <= 10.0f)) {
        warn(file_, name + ": KHR_materials_ior ior must lie in [1, 10]; using 1.5");
        out.ior = 1.5f;
    }
    const tinygltf::Value& transmission = extensionIn(m.extensions, "KHR_materials_transmission");
    out.transmission = float(jsonNumber(transmission, "transmissionFactor", 0.0));
    checkRange(name, "transmissionFactor", out.transmission, 0.0, 1.0);
    const tinygltf::Value& specular = extensionIn(m.extensions, "KHR_materials_specular");
    if (!metallicRoughness) {
        // The specular-glossiness model sets F0 itself; the spec forbids _ior and _specular
        // beside it.
        for (const char* other : {"KHR_materials_ior", "KHR_materials_specular"})
            if (extensionIn(m.extensions, other).IsObject())
                warn(file_, name + ": " + other + " is ignored beside "
                                   "KHR_materials_pbrSpecularGlossiness");
    } else if (specular.IsObject()) {
        out.specular = float(jsonNumber(specular, "specularFactor", 1.0));
        checkRange(name, "specularFactor", out.specular, 0.0, 1.0);
        const std::vector<double> color = jsonNumbers(specular, "specularColorFactor", 3, {1, 1, 1});
        for (int c = 0; c < 3; ++c) {
            checkRange(name, "specularColorFactor", color[c], 0.0, 1e30);
            out.specularColor[c] = float(color[c]);
        }
    }
    convertLayers(m, name, out, needs);
    checkRange(name, "normalTexture.scale", m.normalTexture.scale, -1e30, 1e30);
    out.normalScale = float(m.normalTexture.scale);

    const auto& base = pbr.baseColorTexture;
    const auto& mr = pbr.metallicRoughnessTexture;
    const auto& normal = m.normalTexture;
    const auto& emissive = m.emissiveTexture;
    if (metallicRoughness) {
        out.baseColorTexture = textures_.core(base.index, base.texCoord, base.extensions, true,
                                          name + " baseColorTexture", needs);
        out.metallicRoughnessTexture = textures_.core(mr.index, mr.texCoord, mr.extensions, false,
                                                  name + " metallicRoughnessTexture", needs);
    }
    out.normalTexture = textures_.core(normal.index, normal.texCoord, normal.extensions, false,
                                   name + " normalTexture", needs);
    out.emissiveTexture = textures_.core(emissive.index, emissive.texCoord, emissive.extensions,
                                     true, name + " emissiveTexture", needs);
    out.transmissionTexture =
        textures_.inExtension(transmission, "transmissionTexture", false, name, needs);
    if (!metallicRoughness) {
        convertSpecularGlossiness(specGloss, name, out, needs);
    } else if (specular.IsObject()) {
        out.specularTexture = textures_.inExtension(specular, "specularTexture", false, name, needs);
        out.specularColorTexture =
            textures_.inExtension(specular, "specularColorTexture", true, name, needs);
    }
    convertIridescence(m, name, out, needs);
    // Tangents follow the normal map's UV set, else the coat's normal map's.
    for (uint32_t map : {out.clearcoatNormalTexture, out.normalTexture}) {
        if (map == WF_NO_TEXTURE)
            continue;
        const int set = (tables_.refs[map].flags & WF_TEXTURE_TEXCOORD1) ? 1 : 0;
        if (needs.normalMapTexCoord >= 0 && needs.normalMapTexCoord != set)
            warn(file_, name + ": normalTexture and clearcoatNormalTexture use different UV "
                               "sets; the tangents follow normalTexture's");
        needs.normalMapTexCoord = set;
    }
    convertAnisotropy(m, name, out, needs);
    convertDiffuseTransmission(m, name, out, needs);
    // KHR_materials_dispersion: 20 / Abbe number, any value >= 0 (bsdf/dispersion.h); it acts
    // where the material refracts (gpu_types::materialDisperses).
    const tinygltf::Value& dispersion = extensionIn(m.extensions, "KHR_materials_dispersion");
    if (dispersion.IsObject()) {
        const double value = jsonNumber(dispersion, "dispersion", 0.0);
        if (!(value >= 0.0 && value <= 1e6)) // NaN fails too
            fail(file_, name + ": KHR_materials_dispersion dispersion must be a number in "
                               "[0, 1e6] (20 / Abbe number)");
        out.dispersion = float(value);
    }
    if (extensionIn(m.extensions, "KHR_materials_unlit").IsObject())
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
    out.clearcoatTexture = out.clearcoatRoughnessTexture = out.clearcoatNormalTexture =
        out.sheenColorTexture = out.sheenRoughnessTexture = out.thicknessTexture = WF_NO_TEXTURE;
    out.anisotropyStrength = 0.0f;
    out.anisotropyTexture = WF_NO_TEXTURE;
    out.diffuseTransmission = 0.0f;
    out.diffuseTransmissionTexture = out.diffuseTransmissionColorTexture = WF_NO_TEXTURE;
    out.dispersion = 0.0f;
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

std::vector<uint32_t*> textureFields(Material& m) {
    return {&m.baseColorTexture,     &m.metallicRoughnessTexture, &m.normalTexture,
            &m.emissiveTexture,      &m.transmissionTexture,      &m.specularTexture,
            &m.specularColorTexture, &m.iridescenceTexture,       &m.iridescenceThicknessTexture,
            &m.clearcoatTexture,     &m.clearcoatRoughnessTexture, &m.clearcoatNormalTexture,
            &m.sheenColorTexture,    &m.sheenRoughnessTexture,    &m.thicknessTexture,
            &m.anisotropyTexture,    &m.diffuseTransmissionTexture,
            &m.diffuseTransmissionColorTexture};
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
    m.clearcoatTexture = m.clearcoatRoughnessTexture = m.clearcoatNormalTexture =
        m.sheenColorTexture = m.sheenRoughnessTexture = m.thicknessTexture = WF_NO_TEXTURE;
    m.clearcoatNormalScale = 1.0f;
    m.anisotropyTexture = WF_NO_TEXTURE; // strength 0: isotropic; rotation 0
    m.anisotropyRotation = glm::vec2(1.0f, 0.0f);
    m.diffuseTransmissionColor = glm::vec3(1.0f); // factor 0: no diffuse transmission
    m.diffuseTransmissionTexture = m.diffuseTransmissionColorTexture = WF_NO_TEXTURE;
    return m;
}

MaterialTables convertMaterials(const tinygltf::Model& model, const std::string& file) {
    return MaterialConverter(model, file).run();
}

} // namespace wf::gltf
