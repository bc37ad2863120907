// KHR_materials_anisotropy on the GPU (lavapipe, validation on): a highlight on a metal plane
// under a small light, seen from straight above, stretches along the material's direction in
// the mesh's tangent frame and turns with anisotropyRotation and anisotropyTexture, exactly as
// the spec's frame and bsdf.h evaluated on the CPU predict (second moments of the image); white
// anisotropic spheres never outshine the furnace; scenes without anisotropy compile none of
// its code, and it compiles beside every switch that touches the BSDF or tangent frames.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "analytic_scenes.h"
#include "gpu_test_util.h"
#include "mini_gltf.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/gltf/gltf_loader.h"
#include "shaders/bsdf/bsdf.h"

namespace wf::test {
namespace {

constexpr float HALF = 1.5f;      // the plane and the orthographic view: [-1.5, 1.5]^2
constexpr float LIGHT_Y = 1.0f;   // a point light of intensity 1 above the plane's centre
constexpr uint32_t SIZE = 64;
constexpr float ROUGHNESS = 0.3f;
constexpr float STRENGTH = 0.8f;
// The mesh's tangent T = (cos, 0, sin) of this angle and bitangent B = cross(N, T) = (sin, 0,
// -cos): turned away from the frame the shaders would make up without tangents (x, -z).
constexpr float TANGENT_ANGLE = 2.1f;

// A 1x1 PNG of RGB (128, 255, 191): direction (128, 255) / 255 * 2 - 1 ~ the bitangent,
// strength x 191 / 255.
const char* TEXEL_PNG = "iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAIAAACQd1PeAAAADElEQVR4nGNo+L8fAARBAj8"
                        "UxVG+AAAAAElFTkSuQmCC";

struct Plane {
    const char* name;
    float strength;
    float rotation;   // anisotropyRotation, radians
    bool tangents;    // a TANGENT attribute (1, 0, 0, 1); else MikkTSpace from the UVs
    bool texture;     // anisotropyTexture = TEXEL_PNG
};

glm::vec3 meshTangent() {
    return glm::vec3(std::cos(TANGENT_ANGLE), 0.0f, std::sin(TANGENT_ANGLE));
}

glm::vec3 meshBitangent() {
    return glm::cross(glm::vec3(0, 1, 0), meshTangent());
}

// A white metal quad at y = 0 facing +y with TANGENT (T, 1) or, without it, UVs whose
// MikkTSpace frame is the same (u = p.T, v = -p.B), an orthographic camera looking down and the
// light at (0, LIGHT_Y, 0).
std::string planeGltf(const TempDir& dir, const Plane& p) {
    MiniGltf g;
    const std::vector<float> corners = {-HALF, 0, -HALF, HALF, 0, -HALF,
                                        HALF,  0, HALF,  -HALF, 0, HALF};
    const int pos = g.addPositions(corners);
    const std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    const glm::vec3 t = meshTangent(), b = meshBitangent();
    std::vector<float> uvs, tangents;
    for (int k = 0; k < 4; ++k) {
        const glm::vec3 corner(corners[3 * k], 0.0f, corners[3 * k + 2]);
        uvs.insert(uvs.end(), {glm::dot(corner, t), -glm::dot(corner, b)});
        tangents.insert(tangents.end(), {t.x, t.y, t.z, 1.0f});
    }
    const int normal = g.addAccessor(g.addView(normals.data(), 48), F32, 4, "VEC3");
    const int uv = g.addAccessor(g.addView(uvs.data(), 32), F32, 4, "VEC2");
    const int tangent = g.addAccessor(g.addView(tangents.data(), 64), F32, 4, "VEC4");
    std::string attributes = ",\"NORMAL\":" + std::to_string(normal) +
                             ",\"TEXCOORD_0\":" + std::to_string(uv);
    if (p.tangents)
        attributes += ",\"TANGENT\":" + std::to_string(tangent);
    g.addMesh(pos, g.addIndices<uint16_t>({0, 2, 1, 0, 3, 2}, U16), 0, 4, attributes);
    char anisotropy[160];
    std::snprintf(anisotropy, sizeof anisotropy,
                  R"("anisotropyStrength":%.9g,"anisotropyRotation":%.9g)", p.strength,
                  p.rotation);
    g.materials.push_back(
        std::string(R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1],"metallicFactor":1,)") +
        R"("roughnessFactor":0.3},"extensions":{"KHR_materials_anisotropy":{)" + anisotropy +
        (p.texture ? R"(,"anisotropyTexture":{"index":0})" : "") + "}}}");
    if (p.texture) {
        g.images.push_back(std::string(R"({"uri":"data:image/png;base64,)") + TEXEL_PNG + "\"}");
        g.textures.push_back(R"({"source":0})");
    }
    g.cameras.push_back(R"({"type":"orthographic","orthographic":{"xmag":1.5,"ymag":1.5,)"
                        R"("znear":0.1,"zfar":100}})");
    g.nodes = {R"({"mesh":0})",
               R"({"camera":0,"translation":[0,5,0],"rotation":[-0.70710678,0,0,0.70710678]})",
               R"({"extensions":{"KHR_lights_punctual":{"light":0}},"translation":[0,1,0]})"};
    g.scenes = R"([{"nodes":[0,1,2]}])";
    g.extra = R"(,"extensionsUsed":["KHR_materials_anisotropy","KHR_lights_punctual"],)"
              R"("extensions":{"KHR_lights_punctual":{"lights":[{"type":"point","intensity":1}]}})";
    return g.write(dir);
}

// What the spec and bsdf.h give each pixel (4x4 points across it, as the box filter averages):
// the direction cos(rotation) T + sin(rotation) B in the mesh's tangent frame (of the texel's
// direction), radiance f(wo, wi) I cos / d^2 with wo straight up. Row r looks at z > 0 for
// large r (the camera's up is -z).
std::vector<float> expectedImage(const Plane& p) {
    float strength = p.strength;
    glm::vec2 d(1.0f, 0.0f);
    if (p.texture) {
        d = glm::vec2(128.0f, 255.0f) / 255.0f * 2.0f - 1.0f;
        strength *= 191.0f / 255.0f;
    }
    const float c = std::cos(p.rotation), s = std::sin(p.rotation);
    d = glm::vec2(c * d.x - s * d.y, s * d.x + c * d.y);
    const glm::vec3 n(0, 1, 0), tangent = glm::normalize(d.x * meshTangent() + d.y * meshBitangent());
    const glm::vec3 bitangent = glm::cross(n, tangent);
    gpu_types::BsdfParams m{glm::vec3(1.0f), 1.0f, ROUGHNESS, 1.5f, 0.0f, 1.0f, glm::vec3(1.0f)};
    m.anisotropy = strength;
    auto local = [&](glm::vec3 w) {
        return glm::vec3(glm::dot(w, tangent), glm::dot(w, bitangent), glm::dot(w, n));
    };
    std::vector<float> image(SIZE * SIZE, 0.0f);
    for (uint32_t r = 0; r < SIZE; ++r)
        for (uint32_t col = 0; col < SIZE; ++col) {
            double sum = 0.0;
            for (int i = 0; i < 4; ++i)
                for (int j = 0; j < 4; ++j) {
                    const float x = -HALF + 2.0f * HALF * (col + (j + 0.5f) / 4.0f) / SIZE;
                    const float z = -HALF + 2.0f * HALF * (r + (i + 0.5f) / 4.0f) / SIZE;
                    const glm::vec3 toLight(-x, LIGHT_Y, -z);
                    const float d2 = glm::dot(toLight, toLight);
                    const glm::vec3 wi = toLight / std::sqrt(d2);
                    sum += gpu_types::bsdfEval(m, local(n), local(wi)).x * wi.y / d2;
                }
            image[r * SIZE + col] = float(sum / 16.0);
        }
    return image;
}

// The image's second moments about its centroid, in scene units along the mesh's T and B.
struct Moments {
    double tt, bb, tb;
};

Moments moments(const std::vector<float>& luminance) {
    double w = 0, mx = 0, mz = 0, xx = 0, zz = 0, xz = 0;
    for (uint32_t r = 0; r < SIZE; ++r)
        for (uint32_t c = 0; c < SIZE; ++c) {
            const double v = luminance[r * SIZE + c];
            const double x = -HALF + 2.0 * HALF * (c + 0.5) / SIZE;
            const double z = -HALF + 2.0 * HALF * (r + 0.5) / SIZE;
            w += v;
            mx += v * x;
            mz += v * z;
            xx += v * x * x;
            zz += v * z * z;
            xz += v * x * z;
        }
    mx /= w;
    mz /= w;
    xx = xx / w - mx * mx;
    zz = zz / w - mz * mz;
    xz = xz / w - mx * mz;
    const glm::dvec2 t(meshTangent().x, meshTangent().z), b(meshBitangent().x, meshBitangent().z);
    auto form = [&](glm::dvec2 u, glm::dvec2 v) {
        return u.x * v.x * xx + (u.x * v.y + u.y * v.x) * xz + u.y * v.y * zz;
    };
    return {form(t, t), form(b, b), form(t, b)};
}

TEST(Anisotropy, HighlightStretchesAlongTheTangentAndTurnsWithRotation) {
    const float quarter = 0.78539816f, half = 1.5707963f;
    const Plane planes[] = {
        {"isotropic", 0.0f, 0.0f, true, false},
        {"along the tangent", STRENGTH, 0.0f, true, false},
        {"rotated 90 degrees", STRENGTH, half, true, false},
        {"rotated 45 degrees", STRENGTH, quarter, true, false},
        {"MikkTSpace tangents, rotated -30 degrees", STRENGTH, -0.52359878f, false, false},
        {"texture: the bitangent", STRENGTH, 0.0f, true, true},
    };
    RenderSettings settings;
    settings.width = settings.height = SIZE;
    settings.samplesPerPixel = 16;
    settings.maxDepth = 2; // direct light only: no noise but the pixel filter's
    settings.seed = 5;
    for (const Plane& p : planes) {
        TempDir dir;
        const RenderResult result = renderScene(loadGltf(planeGltf(dir, p)), settings);
        std::vector<float> image(SIZE * SIZE);
        for (uint32_t i = 0; i < SIZE * SIZE; ++i)
            image[i] = result.rgb[3 * i];
        const std::vector<float> expected = expectedImage(p);
        double diff = 0.0, total = 0.0;
        for (uint32_t i = 0; i < SIZE * SIZE; ++i) {
            diff += std::abs(image[i] - expected[i]);
            total += expected[i];
        }
        const Moments m = moments(image), e = moments(expected);
        std::printf("anisotropy %-40s TT %.4f BB %.4f TB %+.4f (expected %.4f %.4f %+.4f), "
                    "L1 %.4f\n",
                    p.name, m.tt, m.bb, m.tb, e.tt, e.bb, e.tb, diff / total);
        EXPECT_LT(diff / total, 0.03) << p.name;
        const double scale = m.tt + m.bb;
        EXPECT_NEAR(m.tt, e.tt, 0.03 * scale) << p.name;
        EXPECT_NEAR(m.bb, e.bb, 0.03 * scale) << p.name;
        EXPECT_NEAR(m.tb, e.tb, 0.03 * scale) << p.name;
        // The shape itself, whatever the reference says: stretched along T at rotation 0,
        // along B at 90 degrees and for the texel, along (T + B) / sqrt 2 at 45.
        const double along = p.rotation == 0.0f && !p.texture ? m.tt / m.bb : m.bb / m.tt;
        if (p.strength == 0.0f)
            EXPECT_NEAR(m.tt / m.bb, 1.0, 0.05) << p.name;
        else if (p.rotation != quarter && p.rotation > -0.5f)
            EXPECT_GT(along, 3.0) << p.name;
        if (p.rotation == quarter)
            EXPECT_GT(m.tb, 0.5 * std::sqrt(m.tt * m.bb)) << p.name;
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

gpu_types::Material anisotropic(float metallic, float roughness, float transmission,
                                float strength) {
    gpu_types::Material m{};
    m.baseColor = glm::vec4(1.0f);
    m.metallic = metallic;
    m.roughness = roughness;
    m.ior = 1.5f;
    m.transmission = transmission;
    m.specular = 1.0f;
    m.specularColor = glm::vec3(1.0f);
    m.anisotropyStrength = strength;
    m.anisotropyTexture = WF_NO_TEXTURE;
    m.anisotropyRotation = glm::vec2(std::cos(0.4f), std::sin(0.4f));
    return m;
}

// The white furnace of tests/gpu/test_material_furnace.cpp for the anisotropic lobes (the
// sphere has no tangents: the direction turns about an arbitrary frame, which is all a furnace
// needs). Nothing outshines the environment; the nearly smooth mirror (alphas 0.01 and 1e-4)
// very nearly vanishes, as the lossless mirror it tends to does.
TEST(Anisotropy, WhiteFurnaceNeverCreatesEnergy) {
    struct Case {
        const char* name;
        gpu_types::Material material;
        bool nearlyLossless;
    };
    const Case cases[] = {
        {"metal 0.3", anisotropic(1.0f, 0.3f, 0.0f, 1.0f), false},
        {"white dielectric 0.5", anisotropic(0.0f, 0.5f, 0.0f, 1.0f), false},
        {"rough glass 0.3", anisotropic(0.0f, 0.3f, 1.0f, 0.8f), false},
        {"nearly smooth mirror", anisotropic(1.0f, 0.0f, 0.0f, 0.1f), true},
    };
    for (const Case& c : cases) {
        for (LightSampling sampling : {LightSampling::Bsdf, LightSampling::Mis}) {
            RenderSettings settings;
            settings.width = settings.height = 24;
            settings.samplesPerPixel = 64;
            settings.maxDepth = 64;
            settings.lightSampling = sampling;
            settings.seed = 78;
            const RenderResult result = renderScene(furnaceSphere(c.material, 1.0f), settings);
            EXPECT_EQ(result.stats.nonFiniteSamples, 0u);
            const MeanAndError m = imageMean(result.rgb);
            std::printf("anisotropic furnace %-22s %-4s %.4f +- %.4f\n", c.name,
                        lightSamplingName(sampling), m.mean, m.standardError);
            EXPECT_LE(m.mean, 1.0 + 4.0 * m.standardError + 2e-3) << c.name;
            EXPECT_GT(m.mean, 0.5) << c.name; // something was measured
            if (c.nearlyLossless)
                EXPECT_NEAR(m.mean, 1.0, 4.0 * m.standardError + 5e-3) << c.name;
        }
    }
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

bool spirvMentions(const std::vector<uint32_t>& spirv, const char* name) {
    const char* bytes = reinterpret_cast<const char*>(spirv.data());
    return std::string(bytes, spirv.size() * 4).find(name) != std::string::npos;
}

// WF_HAS_ANISOTROPY is defined only for scenes that use it, and brings its code only then.
TEST(Anisotropy, SceneWithoutItCompilesNoneOfItsCode) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    RenderSettings settings;
    settings.width = settings.height = 8;
    settings.samplesPerPixel = 1;
    settings.maxDepth = 2;
    PreparedScene plain = prepareScene(
        furnaceSphere(anisotropic(1.0f, 0.3f, 0.0f, 0.0f), 1.0f)); // strength 0: isotropic
    WavefrontRenderer renderer(gpuContext(), plain, settings, compiler);
    ShaderDefines defines = renderer.shaderDefines();
    for (const auto& [key, value] : defines)
        EXPECT_TRUE(key != "WF_HAS_ANISOTROPY" && key != "WF_HAS_TANGENTS") << key;
    for (const char* pass : {"shade.comp", "megakernel.comp"})
        EXPECT_FALSE(spirvMentions(compiler.compile(pass, defines).spirv, "anisotropyAt"))
            << pass;
    PreparedScene stretched = prepareScene(furnaceSphere(anisotropic(1.0f, 0.3f, 0.0f, 1.0f), 1.0f));
    WavefrontRenderer on(gpuContext(), stretched, settings, compiler);
    for (const char* pass : {"shade.comp", "megakernel.comp"})
        EXPECT_TRUE(spirvMentions(compiler.compile(pass, on.shaderDefines()).spirv,
                                  "anisotropyAt"))
            << pass;
    EXPECT_EQ(gpuContext().validationMessageCount(), 0u);
}

// The switch compiles beside every other that touches the BSDF or the tangent frames: with
// and without tangent data, textures and normal maps, the layered BSDF, path guiding, and in
// the shade kinds' own BSDFs (Dirac only, Lambert only).
TEST(Anisotropy, CompilesWithTheOtherMaterialSwitches) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    for (int bits = 0; bits < 16; ++bits)
        for (const char* pass : {"shade.comp", "megakernel.comp"}) {
            const bool textures = bits & 2;
            ShaderDefines defines = {{"WF_WORKGROUP_SIZE", "64"},
                                     {"WF_HAS_EMITTERS", "1"},
                                     {"WF_HAS_TRIANGLE_EMITTERS", "1"},
                                     {"WF_LIGHT_SAMPLING", "2"},
                                     {"WF_HAS_NORMALS", "1"},
                                     {"WF_HAS_TEXTURES", textures ? "1" : "0"},
                                     {"WF_TEXEL_PAGES", textures ? "1" : "0"},
                                     {"WF_HAS_NORMAL_MAPS", textures ? "1" : "0"},
                                     {"WF_RAY_CONES", textures ? "1" : "0"},
                                     {"WF_HAS_CLEARCOAT", bits & 4 ? "1" : "0"},
                                     {"WF_HAS_SHEEN", bits & 4 ? "1" : "0"},
                                     {"WF_GUIDING", bits & 8 ? "1" : "0"},
                                     {"WF_HAS_ANISOTROPY", "1"},
                                     {"WF_HAS_TANGENTS", bits & 1 ? "1" : "0"}};
            ASSERT_GT(compiler.compile(pass, defines).spirv.size(), 5u) << pass << " " << bits;
        }
    for (const char* only : {"WF_BSDF_DELTA_ONLY", "WF_BSDF_DIFFUSE_ONLY"}) {
        ShaderDefines defines = {{"WF_WORKGROUP_SIZE", "64"}, {"WF_HAS_EMITTERS", "1"},
                                 {"WF_HAS_ANISOTROPY", "1"}, {only, "1"}};
        ASSERT_GT(compiler.compile("shade.comp", defines).spirv.size(), 5u) << only;
    }
}

} // namespace
} // namespace wf::test
