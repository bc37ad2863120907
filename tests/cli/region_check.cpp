// wf_region_check: are independent renders unbiased against a reference?
//   wf_region_check REFERENCE.exr RUN1.exr RUN2.exr ... [--sigmas K]
//   wf_region_check --same A.exr B.exr: the two images' pixels are equal, bit for bit
// The runs (one per seed, at least 4) and the reference must have one size. Per 8x8 region
// and channel, the runs' mean of region means must lie within K (default 5) standard errors
// of the reference's region mean, the standard error taken from the runs' spread across seeds
// (plus a floor of 1e-4 relative, for flat black regions). Exit 0 when every region agrees,
// 1 otherwise (naming the worst region), 2 on bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "image/exr_io.h"

int main(int argc, char** argv) {
    if (argc == 4 && std::string(argv[1]) == "--same") {
        try {
            const wf::ExrImage a = wf::readExr(argv[2]), b = wf::readExr(argv[3]);
            const bool same = a.width == b.width && a.height == b.height && a.rgb == b.rgb;
            std::printf("%s %s and %s\n", same ? "ok   same pixels:" : "FAIL differ:", argv[2],
                        argv[3]);
            return same ? 0 : 1;
        } catch (const std::exception& e) {
            std::fprintf(stderr, "wf_region_check: %s\n", e.what());
            return 2;
        }
    }
    std::vector<std::string> runs;
    double sigmas = 5.0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--sigmas" && i + 1 < argc)
            sigmas = std::atof(argv[++i]);
        else
            runs.push_back(arg);
    }
    if (runs.size() < 5) {
        std::fprintf(stderr, "usage: wf_region_check REFERENCE.exr RUN.exr x4 or more "
                             "[--sigmas K]\n");
        return 2;
    }
    try {
        const wf::ExrImage reference = wf::readExr(runs.front());
        runs.erase(runs.begin());
        std::vector<wf::ExrImage> images;
        for (const std::string& path : runs) {
            images.push_back(wf::readExr(path));
            if (images.back().width != reference.width ||
                images.back().height != reference.height) {
                std::fprintf(stderr, "%s: not the reference's size\n", path.c_str());
                return 2;
            }
        }
        const int w = reference.width, h = reference.height;
        auto regionMean = [&](const wf::ExrImage& image, int rx, int ry, int c) {
            double sum = 0.0;
            int n = 0;
            for (int y = ry * 8; y < std::min(h, ry * 8 + 8); ++y)
                for (int x = rx * 8; x < std::min(w, rx * 8 + 8); ++x, ++n)
                    sum += image.rgb[(size_t(y) * w + x) * 3 + c];
            return sum / n;
        };
        double worst = 0.0;
        std::string where;
        int regions = 0;
        for (int ry = 0; ry * 8 < h; ++ry)
            for (int rx = 0; rx * 8 < w; ++rx)
                for (int c = 0; c < 3; ++c) {
                    const double ref = regionMean(reference, rx, ry, c);
                    double mean = 0.0, squares = 0.0;
                    for (const auto& image : images) {
                        const double m = regionMean(image, rx, ry, c);
                        if (!std::isfinite(m)) {
                            std::printf("FAIL %s: non-finite pixels\n", runs.front().c_str());
                            return 1;
                        }
                        mean += m;
                        squares += m * m;
                    }
                    const double n = double(images.size());
                    mean /= n;
                    const double variance = std::max(0.0, (squares / n - mean * mean) * n / (n - 1));
                    const double se = std::sqrt(variance / n) + 1e-4 * std::abs(ref) + 1e-7;
                    const double z = std::abs(mean - ref) / se;
                    ++regions;
                    if (z > worst) {
                        worst = z;
                        where = "region (" + std::to_string(rx) + ", " + std::to_string(ry) +
                                ") channel " + std::to_string(c) + ": mean " +
                                std::to_string(mean) + ", reference " + std::to_string(ref);
                    }
                }
        std::printf("%s %zu runs, %d region-channels, worst %.2f SE at %s\n",
                    worst <= sigmas ? "ok  " : "FAIL", images.size(), regions, worst,
                    where.c_str());
        return worst <= sigmas ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "wf_region_check: %s\n", e.what());
        return 2;
    }
}
