// wavefront merge: the parts of one render (--spp-offset) into one image, checked first
// (image/render_parts.h).
#include <cstdio>
#include <filesystem>

#include "app/cli.h"
#include "app/commands.h"
#include "app/render_options.h"
#include "errors.h"
#include "image/render_parts.h"

namespace fs = std::filesystem;

namespace wf {
namespace {

const CommandSpec& mergeSpec() {
    static const CommandSpec spec{
        "merge",
        "wavefront merge PART.exr [PART.exr ...] -o OUT.exr [options]",
        "Merges parts of one render made with --spp-offset (same scene file, settings, seed and\n"
        "size) into the image one run of all their samples gives: their sample-weighted mean,\n"
        "with the merged sample ranges in the header (sppRanges), and a PNG preview beside it.\n"
        "Refuses parts of another render or with overlapping sample ranges; reports gaps.",
        {
            {"--output", "-o", "OUT.exr", "the merged OpenEXR file (required; must end in .exr)"},
            {"--quiet", "-q", "", "no summary line on stderr"},
            {"--tonemap", "", "MODE", tonemapHelp()},
        },
        "Exit codes: 0 done, 2 bad usage or bad input (one line naming the part), 1 internal\n"
        "failure.\n"};
    return spec;
}

} // namespace

std::string mergeHelp() { return helpText(mergeSpec()); }

int runMergeCommand(const std::vector<std::string>& args) {
    ParsedArgs parsed = parseArgs(mergeSpec(), args);
    if (parsed.has("--help")) {
        std::fputs(mergeHelp().c_str(), stdout);
        return 0;
    }
    auto output = parsed.value("--output");
    if (!output || output->empty())
        throw UsageError("merge needs -o OUT.exr (see wavefront merge --help)");
    if (fs::path(*output).extension() != ".exr")
        throw UsageError("output file must end in .exr, got '" + *output + "'");
    if (parsed.positional.empty())
        throw UsageError("merge needs at least one PART.exr (see wavefront merge --help)");
    std::vector<RenderPart> parts;
    for (const std::string& path : parsed.positional)
        parts.push_back(readRenderPart(path));
    const MergedRender merged = mergeRenderParts(parts);
    RenderPart image = merged.image;
    image.previewTonemap = previewTonemapFrom(parsed);
    for (const std::string& gap : merged.gaps)
        std::fprintf(stderr, "wavefront: merge: samples %s are in no part (the image is the "
                             "mean of the others, still unbiased)\n",
                     gap.c_str());
    writeRenderPart(*output, image, {{"sppRanges", merged.ranges}});
    if (!parsed.has("--quiet"))
        std::fprintf(stderr, "wavefront: merged %zu parts, samples %s (%u spp), into %s\n",
                     parts.size(), merged.ranges.c_str(), image.spp, output->c_str());
    return 0;
}

} // namespace wf
