#include "scene/lights/environment_map.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "errors.h"

namespace wf {
namespace {

// 2x2 box filter (odd edges repeat), keeping the mean radiance of each region.
Environment halve(const Environment& in) {
    Environment out;
    out.width = std::max(1u, in.width / 2);
    out.height = std::max(1u, in.height / 2);
    out.rgb.assign(size_t(out.width) * out.height * 3, 0.0f);
    for (uint32_t y = 0; y < out.height; ++y)
        for (uint32_t x = 0; x < out.width; ++x)
            for (uint32_t k = 0; k < 4; ++k) {
                const size_t sx = std::min(2 * x + (k & 1), in.width - 1);
                const size_t sy = std::min(2 * y + (k >> 1), in.height - 1);
                for (int c = 0; c < 3; ++c)
                    out.rgb[(size_t(y) * out.width + x) * 3 + c] +=
                        0.25f * in.rgb[(sy * in.width + sx) * 3 + c];
            }
    return out;
}

} // namespace

Environment loadEnvironmentExr(const std::string& path) {
    auto fail = [&](const std::string& problem) -> Environment {
        throw InputError(path + ": " + problem);
    };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        return fail("environment map not found or not a regular file");
    Environment env;
    try {
        Imf::InputFile file(path.c_str());
        const Imath::Box2i window = file.header().dataWindow();
        const int64_t width = int64_t(window.max.x) - window.min.x + 1;
        const int64_t height = int64_t(window.max.y) - window.min.y + 1;
        if (width < 1 || height < 1 || width > MAX_ENVIRONMENT_SIDE ||
            height > MAX_ENVIRONMENT_SIDE || size_t(width * height) > MAX_ENVIRONMENT_FILE_PIXELS)
            return fail("environment map of " + std::to_string(width) + "x" +
                        std::to_string(height) + " pixels is empty or over the limit of " +
                        std::to_string(MAX_ENVIRONMENT_SIDE) + " per side and " +
                        std::to_string(MAX_ENVIRONMENT_FILE_PIXELS >> 20) + " Mpixels");
        const Imf::ChannelList& channels = file.header().channels();
        for (const char* name : {"R", "G", "B"})
            if (!channels.findChannel(name))
                return fail(std::string("environment map has no ") + name + " channel");
        env.width = uint32_t(width);
        env.height = uint32_t(height);
        env.rgb.assign(size_t(width) * size_t(height) * 3, 0.0f);
        Imf::FrameBuffer frame;
        const char* names[3] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c) {
            // The slice's base is where pixel (0, 0) of the data window's frame would lie.
            float* base = env.rgb.data() + c - (int64_t(window.min.y) * width + window.min.x) * 3;
            frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(base),
                                              sizeof(float) * 3, sizeof(float) * 3 * width));
        }
        file.setFrameBuffer(frame);
        file.readPixels(window.min.y, window.max.y);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& error) {
        return fail(std::string("cannot read environment map: ") + error.what());
    }
    size_t bad = 0;
    for (float& v : env.rgb)
        if (!(v >= 0.0f && v <= 3.0e38f)) { // NaN, infinite or negative
            v = 0.0f;
            ++bad;
        }
    if (bad > 0)
        std::fprintf(stderr, "warning: %s: %zu NaN, infinite or negative values set to 0\n",
                     path.c_str(), bad);
    while (size_t(env.width) * env.height > MAX_ENVIRONMENT_PIXELS)
        env = halve(env);
    return env;
}

} // namespace wf
