// Every pass shader compiles with glslang in every variant the host can ask for, with the
// on-disk cache off so that nothing stale hides an error.
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "gpu/shader_compiler.h"
#include "passes/workgroup.h"

namespace wf::test {
namespace {

TEST(Shaders, EveryPassCompilesInEveryVariant) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    int compiled = 0;
    for (const auto& entry : std::filesystem::directory_iterator(compiler.shaderDir())) {
        if (entry.path().extension() != ".comp")
            continue;
        const std::string name = entry.path().filename().string();
        const bool lightPass = name.rfind("light_", 0) == 0;
        // Emitters off and on with the path tracer, and on with light tracing and BDPT (a
        // scene without emitters traces paths whatever --integrator says).
        for (const auto& [emitters, integrator] :
             std::initializer_list<std::pair<const char*, const char*>>{
                 {"0", nullptr}, {"1", nullptr}, {"1", "1"}, {"1", "2"}}) {
            if (name == "shadow.comp" && emitters[0] == '0')
                continue; // no emitters, no shadow rays: the host never builds this variant
            if (lightPass && !integrator)
                continue; // light subpaths' passes exist only for --integrator light and bdpt
            ShaderDefines defines = {{"WF_WORKGROUP_SIZE", std::to_string(kWorkgroupSize)},
                                     {"WF_HAS_EMITTERS", emitters}};
            if (integrator)
                defines.emplace_back("WF_INTEGRATOR", integrator);
            CompiledShader shader = compiler.compile(name, defines);
            EXPECT_FALSE(shader.fromCache);
            ASSERT_GT(shader.spirv.size(), 5u) << entry.path();
            EXPECT_EQ(shader.spirv[0], 0x07230203u);
            ++compiled;
        }
    }
    EXPECT_GE(compiled, 11);
}

// The ray-tracing passes' shaders (--traversal rt) compile wherever glslang runs, also where
// no device has ray-tracing pipelines to run them (Mesa 22.3's lavapipe), in the switches
// their host side sets: instances, alpha tests, sphere lights, the shadow copy, shade bins.
TEST(Shaders, RayTracingShadersCompileInEveryVariant) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    int compiled = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(compiler.shaderDir()) / "rt")) {
        for (int bits = 0; bits < 16; ++bits) {
            if (entry.path().filename() == "sphere.rint" && !(bits & 4))
                continue; // the host compiles it only for scenes with sphere lights
            ShaderDefines defines = {{"WF_WORKGROUP_SIZE", std::to_string(kWorkgroupSize)},
                                     {"WF_HAS_EMITTERS", "1"},
                                     {"WF_RAY_TRACING", "1"},
                                     {"WF_HAS_INSTANCES", bits & 1 ? "1" : "0"},
                                     {"WF_HAS_ALPHA_MASK", bits & 2 ? "1" : "0"},
                                     {"WF_HAS_SPHERE_LIGHTS", bits & 4 ? "1" : "0"},
                                     {"WF_HAS_LIGHTS", bits & 4 ? "1" : "0"},
                                     {"WF_RT_SHADOW", bits & 8 ? "1" : "0"}};
            if (bits & 8) {
                defines.emplace_back("WF_SHADE_BINS", "3");
                defines.emplace_back("WF_LIGHT_HIT_BIN", "2");
            }
            CompiledShader shader =
                compiler.compile("rt/" + entry.path().filename().string(), defines);
            ASSERT_GT(shader.spirv.size(), 5u) << entry.path();
            EXPECT_EQ(shader.spirv[0], 0x07230203u);
            ++compiled;
        }
    }
    EXPECT_GE(compiled, 6 * 16 + 8);
}

// The path guide's code (WF_GUIDING) in every shader that holds it, with MIS, with and
// without the layered BSDF.
TEST(Shaders, GuidedPassesCompile) {
    ShaderCompiler compiler(defaultShaderDir(), "");
    for (const char* file : {"raygen.comp", "shade.comp", "accumulate.comp", "megakernel.comp"})
        for (const char* layers : {"0", "1"}) {
            ShaderDefines defines = {{"WF_WORKGROUP_SIZE", std::to_string(kWorkgroupSize)},
                                     {"WF_HAS_EMITTERS", "1"},
                                     {"WF_HAS_TRIANGLE_EMITTERS", "1"},
                                     {"WF_LIGHT_SAMPLING", "2"},
                                     {"WF_HAS_CLEARCOAT", layers},
                                     {"WF_GUIDING", "1"}};
            CompiledShader shader = compiler.compile(file, defines);
            ASSERT_GT(shader.spirv.size(), 5u) << file;
        }
}

TEST(Shaders, ABrokenShaderReportsGlslangLogWithFileName) {
    auto dir = std::filesystem::temp_directory_path() / "wf_broken_shader_test";
    std::filesystem::create_directories(dir);
    {
        std::ofstream(dir / "raygen.comp") << "\n"; // what marks a shader folder
        std::ofstream(dir / "broken.comp") << "#version 460\nvoid main() { undefined_call(); }\n";
    }
    ShaderCompiler compiler(dir.string(), "");
    try {
        compiler.compile("broken.comp", {});
        FAIL() << "a broken shader compiled";
    } catch (const std::exception& error) {
        EXPECT_NE(std::string(error.what()).find("broken.comp"), std::string::npos);
        EXPECT_NE(std::string(error.what()).find("undefined_call"), std::string::npos);
    }
    std::filesystem::remove_all(dir);
}

TEST(Shaders, SecondCompileComesFromTheCache) {
    auto cache = std::filesystem::temp_directory_path() / "wf_spirv_cache_test";
    std::filesystem::remove_all(cache);
    ShaderCompiler compiler(defaultShaderDir(), cache.string());
    ShaderDefines defines = {{"WF_WORKGROUP_SIZE", "64"}, {"WF_HAS_EMITTERS", "1"}};
    CompiledShader first = compiler.compile("shade.comp", defines);
    CompiledShader second = compiler.compile("shade.comp", defines);
    EXPECT_FALSE(first.fromCache);
    EXPECT_TRUE(second.fromCache);
    EXPECT_EQ(first.spirv, second.spirv);
    defines[1].second = "0";
    EXPECT_FALSE(compiler.compile("shade.comp", defines).fromCache);
    std::filesystem::remove_all(cache);
}

} // namespace
} // namespace wf::test
