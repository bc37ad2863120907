// --env EXR loading and --camera selection: sizes checked before pixels are read, bad texels
// zeroed, cameras found by name or index, and one clear InputError otherwise.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "errors.h"
#include "image/exr_io.h"
#include "scene/default_camera.h"
#include "scene/lights/environment_map.h"

namespace wf {
namespace {

std::string tempPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("wf_env_" + name)).string();
}

TEST(EnvironmentMap, LoadsAndZeroesNonFiniteOrNegativeTexels) {
    const std::string path = tempPath("small.exr");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    writeExr(path, 4, 2, {1, 2, 3, nan, 1, 1, -1, 1, 1, inf, 0, 0, 0.5f, 0.5f, 0.5f, 0, 0, 0,
                          1, 1, 1, 2, 2, 2});
    ::testing::internal::CaptureStderr();
    Environment env = loadEnvironmentExr(path);
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(err.find("3 NaN, infinite or negative"), std::string::npos) << err;
    ASSERT_EQ(env.width, 4u);
    ASSERT_EQ(env.height, 2u);
    EXPECT_EQ(env.rgb[0], 1.0f);
    EXPECT_EQ(env.rgb[3], 0.0f); // NaN
    EXPECT_EQ(env.rgb[6], 0.0f); // negative
    EXPECT_EQ(env.rgb[9], 0.0f); // infinite
    EXPECT_EQ(env.rgb[23], 2.0f);
    std::filesystem::remove(path);
}

TEST(EnvironmentMap, OversizedOrBrokenFilesAreRefusedInOneLine) {
    const std::string wide = tempPath("wide.exr");
    writeExr(wide, 40000, 1, std::vector<float>(40000 * 3, 1.0f));
    try {
        loadEnvironmentExr(wide);
        FAIL() << "a 40000-pixel-wide map loaded";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("over the limit"), std::string::npos) << e.what();
    }
    const std::string broken = tempPath("broken.exr");
    std::ofstream(broken) << "v/1\x01 not really an EXR file";
    for (const std::string& path : {broken, tempPath("missing.exr")}) {
        try {
            loadEnvironmentExr(path);
            FAIL() << path << " loaded";
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        }
    }
    std::filesystem::remove(wide);
    std::filesystem::remove(broken);
}

TEST(EnvironmentMap, LargeMapsAreHalvedKeepingTheirMean) {
    const std::string path = tempPath("large.exr");
    const int w = 4200, h = 2100; // over 2^23 pixels: halved once
    std::vector<float> rgb(size_t(w) * h * 3, 0.0f);
    for (size_t i = 0; i < rgb.size(); i += 6)
        rgb[i] = 2.0f; // every other pixel's red is 2: mean 1
    writeExr(path, w, h, rgb);
    Environment env = loadEnvironmentExr(path);
    EXPECT_EQ(env.width, 2100u);
    EXPECT_EQ(env.height, 1050u);
    EXPECT_NEAR(env.rgb[0], 1.0f, 1e-6f);
    std::filesystem::remove(path);
}

TEST(CameraSelection, ByNameThenIndex) {
    Scene scene;
    Camera a, b;
    a.yfov = 0.5f;
    b.yfov = 0.7f;
    scene.cameras = {a, b};
    scene.cameraNames = {"front", "1"}; // a name that looks like an index wins as a name
    EXPECT_FLOAT_EQ(selectCamera(scene, "front", "s.gltf").yfov, 0.5f);
    EXPECT_FLOAT_EQ(selectCamera(scene, "1", "s.gltf").yfov, 0.7f);
    EXPECT_FLOAT_EQ(selectCamera(scene, "0", "s.gltf").yfov, 0.5f);
    try {
        selectCamera(scene, "side", "s.gltf");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_STREQ(e.what(), "s.gltf: no camera 'side'; the file has 0 'front', 1 '1'");
    }
    EXPECT_THROW(selectCamera(Scene{}, "0", "s.gltf"), InputError);
    EXPECT_THROW(selectCamera(scene, "99999999999999", "s.gltf"), InputError);
}

} // namespace
} // namespace wf
