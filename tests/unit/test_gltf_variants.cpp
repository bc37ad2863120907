// KHR_materials_variants: a chosen variant switches the primitives' materials and nothing else
// (the same triangles in the same places, the same material table), the primitives without a
// mapping for it keep their own; no variant chosen is the primitives' own materials; an unknown
// variant, or one given to a file without variants, is refused in one line; a malformed
// mapping is refused only where the chosen variant needs it, and costs a warning otherwise.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "errors.h"
#include "mini_gltf.h"
#include "scene/gltf/gltf_loader.h"
#include "scene/scene_summary.h"

namespace wf {
namespace {

using test::MiniGltf;
using test::TempDir;

const std::string VARIANTS =
    R"(,"extensionsUsed":["KHR_materials_variants"],"extensions":{"KHR_materials_variants":)"
    R"({"variants":[{"name":"red"},{"name":"blue"}]}})";

std::string material(float r, float g, float b) {
    return R"({"pbrMetallicRoughness":{"baseColorFactor":[)" + std::to_string(r) + "," +
           std::to_string(g) + "," + std::to_string(b) + ",1]}}";
}

// Mesh 0: primitive 0 (material 0; red -> 1, blue -> 2) and primitive 1 (material 0; blue ->
// `blueOfSecond`), at z = 0 and z = 1; mesh 1 at z = 2, material 0 and no mapping. Four
// materials. `extraMapping` is added to primitive 1's mappings.
MiniGltf twoVariants(int blueOfSecond = 3, const std::string& extraMapping = "") {
    MiniGltf g;
    const int a = g.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int b = g.addPositions({0, 0, 1, 1, 0, 1, 0, 1, 1});
    const int c = g.addPositions({0, 0, 2, 1, 0, 2, 0, 1, 2});
    g.meshes.push_back(
        R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(a) +
        R"(},"material":0,"extensions":{"KHR_materials_variants":{"mappings":[)"
        R"({"material":1,"variants":[0]},{"material":2,"variants":[1]}]}}},)"
        R"({"attributes":{"POSITION":)" + std::to_string(b) +
        R"(},"material":0,"extensions":{"KHR_materials_variants":{"mappings":[)"
        R"({"material":)" + std::to_string(blueOfSecond) + R"(,"variants":[1]})" + extraMapping +
        "]}}}]}");
    g.meshes.push_back(R"({"primitives":[{"attributes":{"POSITION":)" + std::to_string(c) +
                       R"(},"material":0}]})");
    g.nodes.push_back(R"({"mesh":0})");
    g.nodes.push_back(R"({"mesh":1})");
    g.scenes = R"([{"nodes":[0,1]}])";
    g.materials = {material(0.5f, 0.5f, 0.5f), material(1, 0, 0), material(0, 0, 1),
                   material(0, 1, 0)};
    g.extra = VARIANTS;
    return g;
}

Scene loadVariant(const std::string& path, const std::string& variant,
                  std::vector<std::string>* warnings = nullptr) {
    GltfOptions options;
    options.variant = variant;
    std::vector<std::string> ignored;
    return loadGltf(path, warnings ? warnings : &ignored, options);
}

std::vector<uint32_t> materialsOf(const Scene& scene) {
    std::vector<uint32_t> out;
    for (const Triangle& t : scene.triangles)
        out.push_back(t.material);
    return out;
}

// Everything but the triangles' material indices is equal.
void expectSameButMaterials(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (size_t i = 0; i < a.triangles.size(); ++i) {
        const Triangle& s = a.triangles[i];
        const Triangle& t = b.triangles[i];
        EXPECT_EQ(s.p0, t.p0) << i;
        EXPECT_EQ(s.p1, t.p1) << i;
        EXPECT_EQ(s.p2, t.p2) << i;
        EXPECT_EQ(s.emitter, t.emitter) << i;
        EXPECT_EQ(s.pad, t.pad) << i;
    }
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i)
        EXPECT_EQ(a.materials[i].baseColor, b.materials[i].baseColor) << i;
    EXPECT_EQ(a.placements.size(), b.placements.size());
    EXPECT_EQ(a.meshes.size(), b.meshes.size());
    EXPECT_EQ(a.lights.size(), b.lights.size());
    EXPECT_EQ(a.cameras.size(), b.cameras.size());
    EXPECT_EQ(a.surface.normals.size(), b.surface.normals.size());
}

std::string inputError(const std::string& path, const std::string& variant) {
    try {
        loadVariant(path, variant);
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "no InputError for --variant " << variant;
    return "";
}

bool anyContains(const std::vector<std::string>& lines, const std::string& text) {
    for (const std::string& line : lines)
        if (line.find(text) != std::string::npos)
            return true;
    return false;
}

TEST(GltfVariants, SwitchMaterialsAndNothingElse) {
    TempDir dir;
    const std::string path = twoVariants().write(dir);
    std::vector<std::string> warnings;
    const Scene plain = loadVariant(path, "", &warnings);
    const Scene red = loadVariant(path, "red");
    const Scene blue = loadVariant(path, "1"); // by index
    EXPECT_EQ(materialsOf(plain), (std::vector<uint32_t>{0, 0, 0})); // their own materials
    EXPECT_EQ(materialsOf(red), (std::vector<uint32_t>{1, 0, 0}));   // no red mapping: own
    EXPECT_EQ(materialsOf(blue), (std::vector<uint32_t>{2, 3, 0}));
    expectSameButMaterials(plain, red);
    expectSameButMaterials(plain, blue);
    EXPECT_EQ(plain.variantNames, (std::vector<std::string>{"red", "blue"}));
    EXPECT_EQ(plain.variant, -1);
    EXPECT_EQ(red.variant, 0);
    EXPECT_EQ(blue.variant, 1);
    EXPECT_EQ(blue.materials[blue.triangles[0].material].baseColor, glm::vec4(0, 0, 1, 1));
    // The extension is read: no "ignoring glTF extension" warning.
    EXPECT_TRUE(warnings.empty()) << warnings.front();
}

TEST(GltfVariants, VerboseListsTheVariants) {
    TempDir dir;
    const std::string path = twoVariants().write(dir);
    const std::string text = describe(summarize(loadVariant(path, "blue")));
    EXPECT_NE(text.find("variants: 0 'red', 1 'blue' (chosen)"), std::string::npos) << text;
    const std::string none = describe(summarize(loadVariant(path, "")));
    EXPECT_NE(none.find("none chosen"), std::string::npos) << none;
}

TEST(GltfVariants, UnknownVariantIsRefused) {
    TempDir dir;
    const std::string path = twoVariants().write(dir);
    EXPECT_NE(inputError(path, "green").find("--variant green: no such variant"),
              std::string::npos);
    EXPECT_NE(inputError(path, "2").find("no such variant"), std::string::npos);
    MiniGltf plain;
    plain.addMesh(plain.addPositions({0, 0, 0, 1, 0, 0, 0, 1, 0}));
    plain.nodes.push_back(R"({"mesh":0})");
    TempDir other;
    EXPECT_NE(inputError(plain.write(other), "red").find("the file has no variants"),
              std::string::npos);
}

TEST(GltfVariants, BadMappingRefusedOnlyWhereTheChosenVariantNeedsIt) {
    TempDir dir;
    // Primitive 1's blue mapping names material 9 (of 4), and a mapping names variant 7.
    const std::string path =
        twoVariants(9, R"(,{"material":1,"variants":[7]})").write(dir);
    const std::string error = inputError(path, "blue");
    EXPECT_NE(error.find("mesh 0 primitive 1"), std::string::npos) << error;
    EXPECT_NE(error.find("material that does not exist"), std::string::npos) << error;
    std::vector<std::string> warnings;
    const Scene red = loadVariant(path, "red", &warnings);
    EXPECT_EQ(materialsOf(red), (std::vector<uint32_t>{1, 0, 0}));
    EXPECT_TRUE(anyContains(warnings, "material that does not exist")) << warnings.size();
    EXPECT_TRUE(anyContains(warnings, "names a variant that does not exist"));
    warnings.clear();
    EXPECT_EQ(materialsOf(loadVariant(path, "", &warnings)), (std::vector<uint32_t>{0, 0, 0}));
    EXPECT_TRUE(anyContains(warnings, "material that does not exist"));
}

} // namespace
} // namespace wf
