// Image output: EXR round trip with metadata, atomic replacement, PNG preview encoding.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "errors.h"
#include "image/atomic_file.h"
#include "image/exr_io.h"
#include "image/png_writer.h"

namespace wf {
namespace {

namespace fs = std::filesystem;

class ImageIo : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("wf_image_io_" + std::string(::testing::UnitTest::GetInstance()
                                                 ->current_test_info()
                                                 ->name()) +
                "_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    std::string file(const std::string& name) const { return (dir_ / name).string(); }
    // Everything in the folder, to catch leftover temporary files.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : fs::directory_iterator(dir_)) {
            names.push_back(entry.path().filename().string());
        }
        std::sort(names.begin(), names.end());
        return names;
    }

    fs::path dir_;
};

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

std::vector<float> gradient(int width, int height) {
    std::vector<float> rgb;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            rgb.insert(rgb.end(), {float(x), float(y) * 0.25f, 1e-3f * float(x + y) + 100.0f});
        }
    }
    return rgb;
}

TEST_F(ImageIo, ExrRoundTripKeepsPixelsAndAttributes) {
    const std::vector<float> rgb = gradient(7, 5);
    writeExr(file("a.exr"), 7, 5, rgb, {{"wf.scene", "cornell_box.gltf"}}, {{"wf.seconds", 1.25f}},
             {{"wf.spp", 64}});
    ExrImage image = readExr(file("a.exr"));
    EXPECT_EQ(image.width, 7);
    EXPECT_EQ(image.height, 5);
    EXPECT_EQ(image.rgb, rgb); // float32 and lossless ZIP: bit-exact
    EXPECT_EQ(readExrAttribute(file("a.exr"), "wf.scene"), "cornell_box.gltf");
    EXPECT_EQ(readExrAttribute(file("a.exr"), "wf.seconds"), "1.25");
    EXPECT_EQ(readExrAttribute(file("a.exr"), "wf.spp"), "64");
    EXPECT_EQ(readExrAttribute(file("a.exr"), "wf.absent"), std::nullopt);
    EXPECT_EQ(listing(), std::vector<std::string>{"a.exr"});
}

TEST_F(ImageIo, ExrTopRowComesFirst) {
    // Top row red, bottom row blue: a flipped writer or reader would swap them.
    std::vector<float> rgb = {1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1};
    writeExr(file("rows.exr"), 2, 2, rgb, {}, {}, {});
    ExrImage image = readExr(file("rows.exr"));
    EXPECT_EQ(image.rgb, rgb);
}

TEST_F(ImageIo, ReadingGarbageIsAnInputError) {
    std::ofstream(file("bad.exr")) << "not an exr file";
    EXPECT_THROW(readExr(file("bad.exr")), InputError);
    EXPECT_THROW(readExr(file("absent.exr")), InputError);
    EXPECT_THROW(readExrAttribute(file("absent.exr"), "x"), InputError);
}

TEST_F(ImageIo, AtomicWriteReplacesTheOldFileAndLeavesNoTemporary) {
    std::ofstream(file("out.txt")) << "old";
    writeFileAtomically(file("out.txt"), [](const std::string& tmp) {
        EXPECT_NE(tmp.find("out.txt.tmp-"), std::string::npos);
        std::ofstream(tmp) << "new";
    });
    EXPECT_EQ(readText(file("out.txt")), "new");
    EXPECT_EQ(listing(), std::vector<std::string>{"out.txt"});
}

TEST_F(ImageIo, FailedAtomicWriteKeepsTheOldFile) {
    std::ofstream(file("out.txt")) << "old";
    EXPECT_THROW(writeFileAtomically(file("out.txt"),
                                     [](const std::string& tmp) {
                                         std::ofstream(tmp) << "half";
                                         throw std::runtime_error("disk full");
                                     }),
                 std::runtime_error);
    EXPECT_EQ(readText(file("out.txt")), "old");
    EXPECT_EQ(listing(), std::vector<std::string>{"out.txt"});
}

TEST_F(ImageIo, WritingIntoAMissingFolderIsAnInputError) {
    const std::string path = file("no/such/folder/out.exr");
    try {
        writeExr(path, 1, 1, {0, 0, 0}, {}, {}, {});
        ADD_FAILURE() << "no InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write " + path + ": folder does not exist");
    }
    EXPECT_THROW(writePngPreview(path, 1, 1, {0, 0, 0}), InputError);
}

TEST_F(ImageIo, PngHasSignatureAndSize) {
    writePngPreview(file("p.png"), 3, 2, gradient(3, 2));
    const std::string bytes = readText(file("p.png"));
    ASSERT_GE(bytes.size(), 24u);
    EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    // IHDR is the first chunk: big-endian width and height at bytes 16 and 20.
    auto be32 = [&](size_t at) {
        return uint32_t(uint8_t(bytes[at])) << 24 | uint32_t(uint8_t(bytes[at + 1])) << 16 |
               uint32_t(uint8_t(bytes[at + 2])) << 8 | uint32_t(uint8_t(bytes[at + 3]));
    };
    EXPECT_EQ(bytes.substr(12, 4), "IHDR");
    EXPECT_EQ(be32(16), 3u);
    EXPECT_EQ(be32(20), 2u);
    EXPECT_EQ(listing(), std::vector<std::string>{"p.png"});
}

TEST(PngTonemap, SrgbEncodingClampsAndZeroesNonFinite) {
    EXPECT_EQ(linearToSrgb8(0.0f), 0);
    EXPECT_EQ(linearToSrgb8(1.0f), 255);
    EXPECT_EQ(linearToSrgb8(7.0f), 255);
    EXPECT_EQ(linearToSrgb8(-1.0f), 0);
    EXPECT_EQ(linearToSrgb8(0.18f), 118); // middle grey: 0.4614 encoded
    EXPECT_EQ(linearToSrgb8(0.001f), 3);  // linear segment: 12.92 * 0.001 * 255 = 3.29
    EXPECT_EQ(linearToSrgb8(std::nanf("")), 0);
    EXPECT_EQ(linearToSrgb8(INFINITY), 0);
}

TEST(ExrLayers, ExtraChannelsRoundTrip) {
    const std::string path = ::testing::TempDir() + "layers.exr";
    writeExr(path, 2, 1, {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f}, {}, {}, {},
             {{"Depth.Z", {1.5f, 2.5f}}, {"Denoising Albedo.R", {0.25f, 0.75f}}});
    EXPECT_EQ(readExrChannel(path, "Depth.Z"), (std::vector<float>{1.5f, 2.5f}));
    EXPECT_EQ(readExrChannel(path, "Denoising Albedo.R"), (std::vector<float>{0.25f, 0.75f}));
    EXPECT_FALSE(readExrChannel(path, "Depth.W").has_value());
    EXPECT_EQ(readExr(path).rgb[4], 0.5f); // the image itself as before
    EXPECT_THROW(writeExr(path, 2, 1, std::vector<float>(6, 0.0f), {}, {}, {},
                          {{"Depth.Z", {1.0f}}}),
                 InternalError);
}

} // namespace
} // namespace wf
