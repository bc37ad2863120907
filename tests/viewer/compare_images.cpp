// wf_compare_images: checks a viewer screenshot against an offscreen render.
//   wf_compare_images VIEW.exr RENDER.exr [--spp N] [--tolerance T] [--shown VIEW.png]
//                     [--tonemap MODE]
// The EXRs must have the same size and agree per channel within T * (1 + |render|) (samples are
// a pure hash of pixel, sample, dimension and seed, so the same spp and seed give the same
// samples; only the grouping of the float sums differs with the viewer's per-frame batches).
// --spp checks VIEW.exr's spp attribute. --shown checks that the PNG of the shown frame (taken
// with --no-overlay) is the radiance through the tone curve (--tonemap, default the viewer's:
// image/tonemap.h), within one 8-bit step.
// On failure a difference image is written beside VIEW.exr (VIEW.diff.exr). Exit 0 or 1.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <stb_image.h>

#include "image/exr_io.h"
#include "image/png_writer.h"
#include "image/tonemap.h"

namespace {

int fail(const std::string& message) {
    std::printf("FAIL %s\n", message.c_str());
    return 1;
}

std::string size(int width, int height) {
    return std::to_string(width) + "x" + std::to_string(height);
}

int checkShown(const std::string& pngPath, const wf::ExrImage& view, wf::Tonemap tonemap) {
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(pngPath.c_str(), &width, &height, &channels, 3);
    if (!pixels)
        return fail(pngPath + ": cannot read the PNG");
    int worst = 0;
    if (width == view.width && height == view.height)
        for (size_t i = 0; i < size_t(width) * height * 3; i += 3) {
            unsigned char expected[3];
            wf::tonemapToSrgb8(&view.rgb[i], tonemap, expected);
            for (int c = 0; c < 3; ++c)
                worst = std::max(worst, std::abs(int(pixels[i + c]) - int(expected[c])));
        }
    stbi_image_free(pixels);
    if (width != view.width || height != view.height)
        return fail(pngPath + ": " + size(width, height) + ", the EXR is " +
                    size(view.width, view.height));
    if (worst > 1)
        return fail(pngPath + ": the shown frame differs from the radiance by " +
                    std::to_string(worst) + " 8-bit steps");
    std::printf("ok   %s: shown frame = radiance through the %s curve (max step %d)\n",
                pngPath.c_str(), wf::tonemapName(tonemap), worst);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s VIEW.exr RENDER.exr [--spp N] [--tolerance T] "
                             "[--shown VIEW.png]\n", argv[0]);
        return 2;
    }
    const std::string viewPath = argv[1], renderPath = argv[2];
    double tolerance = 1e-4;
    std::string spp, shown;
    wf::Tonemap tonemap = wf::kDefaultTonemap;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--spp")
            spp = argv[i + 1];
        else if (flag == "--tolerance")
            tolerance = std::atof(argv[i + 1]);
        else if (flag == "--shown")
            shown = argv[i + 1];
        else if (flag == "--tonemap")
            tonemap = wf::parseTonemap(argv[i + 1]);
    }
    try {
        const wf::ExrImage view = wf::readExr(viewPath);
        const wf::ExrImage render = wf::readExr(renderPath);
        if (view.width != render.width || view.height != render.height)
            return fail(viewPath + ": " + size(view.width, view.height) + ", the render is " +
                        size(render.width, render.height));
        if (!spp.empty() && wf::readExrAttribute(viewPath, "spp") != spp)
            return fail(viewPath + ": spp attribute is " +
                        wf::readExrAttribute(viewPath, "spp").value_or("missing") + ", not " +
                        spp);
        double worst = 0.0, sum = 0.0;
        std::vector<float> diff(view.rgb.size());
        for (size_t i = 0; i < view.rgb.size(); ++i) {
            diff[i] = std::fabs(view.rgb[i] - render.rgb[i]);
            const double relative = diff[i] / (1.0 + std::fabs(render.rgb[i]));
            worst = std::isfinite(relative) ? std::max(worst, relative) : INFINITY;
            sum += relative;
        }
        if (!(worst <= tolerance)) {
            const std::string diffPath =
                std::filesystem::path(viewPath).replace_extension(".diff.exr").string();
            wf::writeExr(diffPath, view.width, view.height, diff);
            return fail(viewPath + ": differs from the render by up to " +
                        std::to_string(worst) + " (tolerance " + std::to_string(tolerance) +
                        "); difference image " + diffPath);
        }
        std::printf("ok   %s: %dx%d, max relative difference %.3g, mean %.3g\n",
                    viewPath.c_str(), view.width, view.height, worst,
                    sum / double(view.rgb.size()));
        return shown.empty() ? 0 : checkShown(shown, view, tonemap);
    } catch (const std::exception& error) {
        return fail(error.what());
    }
}
