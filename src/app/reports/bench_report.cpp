#include "app/reports/bench_report.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "app/reports/stats_json.h"

namespace wf {
namespace {

// The wavefront's passes in wave order; the megakernel and any other pass follow.
const std::vector<std::string> kPassOrder = {
    "raygen", "intersect", "shade diffuse", "shade specular", "shade general", "shade",
    "queue",  "shadow",    "megakernel",    "accumulate"};

std::vector<std::string> passNames(const BenchRun& run) {
    std::vector<std::string> names;
    for (const auto& name : kPassOrder)
        if (run.timed.passMilliseconds.count(name))
            names.push_back(name);
    for (const auto& [name, ms] : run.timed.passMilliseconds)
        if (std::find(names.begin(), names.end(), name) == names.end())
            names.push_back(name);
    return names;
}

Spread passSpread(const BenchRun& run, const std::string& pass) {
    std::vector<double> values;
    for (const FrameSample& frame : run.frames) {
        auto it = frame.passMilliseconds.find(pass);
        values.push_back(it == frame.passMilliseconds.end() ? 0.0 : it->second);
    }
    return spreadOf(values);
}

Spread gpuTotalSpread(const BenchRun& run) {
    std::vector<double> values;
    for (const FrameSample& frame : run.frames) {
        double sum = 0.0;
        for (const auto& [name, ms] : frame.passMilliseconds)
            sum += ms;
        values.push_back(sum);
    }
    return spreadOf(values);
}

Spread frameSpread(const BenchRun& run) {
    std::vector<double> values;
    for (const FrameSample& frame : run.frames)
        values.push_back(frame.seconds * 1e3);
    return spreadOf(values);
}

std::string mega(double perSecond) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3f M", perSecond * 1e-6);
    return text;
}

std::string line(const char* format, auto... values) {
    char text[512];
    std::snprintf(text, sizeof text, format, values...);
    return text;
}

std::string spreadJson(const Spread& s) {
    return "{\"min\": " + jsonNumber(s.min) + ", \"median\": " + jsonNumber(s.median) +
           ", \"max\": " + jsonNumber(s.max) + "}";
}

std::string runJson(const BenchRun& run) {
    const RenderStats& t = run.timed;
    const double seconds = std::max(run.seconds(), 1e-12);
    const uint64_t rays = t.cameraRays + t.extensionRays + t.shadowRays;
    std::ostringstream out;
    out << "{\n      \"frameMilliseconds\": " << spreadJson(frameSpread(run))
        << ",\n      \"gpuMilliseconds\": " << spreadJson(gpuTotalSpread(run))
        << ",\n      \"passMilliseconds\": {";
    bool first = true;
    for (const auto& name : passNames(run)) {
        out << (first ? "" : ", ") << jsonQuoted(name) << ": " << spreadJson(passSpread(run, name));
        first = false;
    }
    out << "},\n      \"seconds\": " << jsonNumber(run.seconds()) << ",\n      \"paths\": "
        << t.paths << ",\n      \"pathsPerSecond\": " << jsonNumber(run.pathsPerSecond())
        << ",\n      \"rays\": {\"camera\": " << t.cameraRays << ", \"extension\": "
        << t.extensionRays << ", \"shadow\": " << t.shadowRays << ", \"total\": " << rays
        << "},\n      \"raysPerSecond\": {\"camera\": " << jsonNumber(t.cameraRays / seconds)
        << ", \"extension\": " << jsonNumber(t.extensionRays / seconds)
        << ", \"shadow\": " << jsonNumber(t.shadowRays / seconds)
        << ", \"total\": " << jsonNumber(rays / seconds) << "},\n      \"waves\": " << t.waves
        << ",\n      \"longestSubmitSeconds\": " << jsonNumber(t.longestSubmitSeconds)
        << ",\n      \"nonFiniteSamples\": " << t.nonFiniteSamples
        << ",\n      \"occupancy\": [";
    const double paths = double(std::max<uint64_t>(t.paths, 1));
    for (size_t d = 0; d < t.depthRays.size(); ++d)
        out << (d ? ", " : "") << "{\"depth\": " << d << ", \"rays\": " << t.depthRays[d]
            << ", \"fraction\": " << jsonNumber(t.depthRays[d] / paths)
            << ", \"shadowRays\": " << t.depthShadowRays[d] << "}";
    out << "],\n      \"memoryBytes\": {";
    uint64_t total = 0;
    for (size_t i = 0; i < run.memory.size(); ++i) {
        out << (i ? ", " : "") << jsonQuoted(run.memory[i].first) << ": " << run.memory[i].second;
        total += run.memory[i].second;
    }
    out << "},\n      \"memoryTotalBytes\": " << total << "\n    }";
    return out.str();
}

} // namespace

double BenchRun::seconds() const {
    double sum = 0.0;
    for (const FrameSample& frame : frames)
        sum += frame.seconds;
    return sum;
}

double BenchRun::pathsPerSecond() const { return timed.paths / std::max(seconds(), 1e-12); }

Spread spreadOf(std::vector<double> values) {
    if (values.empty())
        return {};
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {values.front(), median, values.back()};
}

RenderStats statsBetween(const RenderStats& before, const RenderStats& after) {
    RenderStats d;
    d.samplesPerPixel = after.samplesPerPixel - before.samplesPerPixel;
    d.seconds = after.seconds - before.seconds;
    d.paths = after.paths - before.paths;
    d.cameraRays = after.cameraRays - before.cameraRays;
    d.extensionRays = after.extensionRays - before.extensionRays;
    d.shadowRays = after.shadowRays - before.shadowRays;
    d.nonFiniteSamples = after.nonFiniteSamples - before.nonFiniteSamples;
    d.waves = after.waves - before.waves;
    // The longest submit of the frame is not recoverable from two maxima; the caller tracks it.
    d.longestSubmitSeconds = after.longestSubmitSeconds;
    for (const auto& [pass, ms] : after.passMilliseconds) {
        auto it = before.passMilliseconds.find(pass);
        d.passMilliseconds[pass] = ms - (it == before.passMilliseconds.end() ? 0.0 : it->second);
    }
    d.depthRays = after.depthRays;
    d.depthShadowRays = after.depthShadowRays;
    for (size_t i = 0; i < d.depthRays.size() && i < before.depthRays.size(); ++i) {
        d.depthRays[i] -= before.depthRays[i];
        d.depthShadowRays[i] -= before.depthShadowRays[i];
    }
    return d;
}

std::string benchTable(const BenchSetup& setup, const BenchRun& run) {
    const RenderStats& t = run.timed;
    const double seconds = std::max(run.seconds(), 1e-12);
    std::ostringstream out;
    out << run.kernel << ": " << run.frames.size() << " frames of " << setup.width << "x"
        << setup.height << " x " << setup.samplesPerFrame << " spp, max depth "
        << setup.maxDepth << "\n";
    out << line("  %-14s %10s %10s %10s\n", "ms per frame", "min", "median", "max");
    auto row = [&](const std::string& name, const Spread& s) {
        out << line("  %-14s %10.3f %10.3f %10.3f\n", name.c_str(), s.min, s.median, s.max);
    };
    for (const auto& name : passNames(run))
        row(name == "queue" ? "queue (bookk.)" : name, passSpread(run, name));
    row("GPU total", gpuTotalSpread(run));
    row("frame (wall)", frameSpread(run));
    const uint64_t rays = t.cameraRays + t.extensionRays + t.shadowRays;
    out << "  paths/s " << mega(run.pathsPerSecond()) << "; rays/s: camera "
        << mega(t.cameraRays / seconds) << ", extension " << mega(t.extensionRays / seconds)
        << ", shadow " << mega(t.shadowRays / seconds) << ", total " << mega(rays / seconds)
        << "\n";
    out << line("  %u submits, longest %.1f ms (budget %.0f ms); %llu non-finite samples\n",
                t.waves, t.longestSubmitSeconds * 1e3, setup.submitBudgetSeconds * 1e3,
                static_cast<unsigned long long>(t.nonFiniteSamples));
    out << line("  %-6s %14s %12s %14s\n", "depth", "rays", "of paths", "shadow rays");
    const size_t last = t.depthRays.size() ? t.depthRays.size() - 1 : 0;
    for (size_t d = 0; d < t.depthRays.size(); ++d) {
        if (d >= setup.maxDepth || (t.depthRays[d] == 0 && t.depthShadowRays[d] == 0))
            continue;
        std::string label = std::to_string(d) + (d == last ? "+" : "");
        out << line("  %-6s %14llu %11.2f%% %14llu\n", label.c_str(),
                    static_cast<unsigned long long>(t.depthRays[d]),
                    100.0 * t.depthRays[d] / std::max<uint64_t>(t.paths, 1),
                    static_cast<unsigned long long>(t.depthShadowRays[d]));
    }
    // Device memory, wrapped at 100 columns.
    uint64_t total = 0;
    std::string text = "  device memory:";
    size_t lineStart = 0;
    for (const auto& [name, bytes] : run.memory) {
        std::string item = line(" %s %.2f MiB;", name.c_str(), bytes / 1048576.0);
        if (text.size() - lineStart + item.size() > 100) {
            text += "\n   ";
            lineStart = text.size() - 3;
        }
        text += item;
        total += bytes;
    }
    out << text << line(" total %.2f MiB\n", total / 1048576.0);
    return out.str();
}

std::string benchRatioLine(const BenchRun& wavefront, const BenchRun& megakernel) {
    const double ratio = wavefront.pathsPerSecond() / std::max(megakernel.pathsPerSecond(), 1e-12);
    return line("wavefront / megakernel: %.3f (paths/s %s vs %s, measured in one run, frames "
                "interleaved)\n",
                ratio, mega(wavefront.pathsPerSecond()).c_str(),
                mega(megakernel.pathsPerSecond()).c_str());
}

std::string benchJson(const BenchSetup& setup, const std::vector<BenchRun>& runs) {
    std::ostringstream out;
    out << "{\n  \"scene\": " << jsonQuoted(setup.scene) << ",\n  \"device\": "
        << jsonQuoted(setup.device) << ",\n  \"driver\": " << jsonQuoted(setup.driver)
        << ",\n  \"shaderVariant\": " << jsonQuoted(setup.variant) << ",\n  \"width\": "
        << setup.width << ",\n  \"height\": " << setup.height << ",\n  \"sppPerFrame\": "
        << setup.samplesPerFrame << ",\n  \"maxDepth\": " << setup.maxDepth
        << ",\n  \"seed\": " << setup.seed << ",\n  \"warmupFrames\": " << setup.warmupFrames
        << ",\n  \"frames\": " << setup.frames << ",\n  \"submitBudgetSeconds\": "
        << jsonNumber(setup.submitBudgetSeconds) << ",\n  \"triangles\": " << setup.triangles
        << ",\n  \"instances\": " << setup.instances << ",\n  \"instancedTriangles\": "
        << setup.instancedTriangles << ",\n  \"peakHostMemoryBytes\": "
        << setup.peakHostMemoryBytes << ",\n  \"loadSeconds\": " << jsonNumber(setup.loadSeconds)
        << ",\n  \"materials\": " << setup.materials
        << ",\n  \"bvh\": {\"nodes\": "
        << setup.bvh.nodeCount << ", \"leaves\": " << setup.bvh.leafCount
        << ", \"depth\": " << setup.bvh.maxDepth << ", \"stackNeed\": " << setup.bvh.stackNeed
        << ", \"traversalCost\": " << jsonNumber(setup.bvh.traversalCost) << ", \"sahCost\": "
        << jsonNumber(setup.bvh.sahCost) << ", \"buildSeconds\": "
        << jsonNumber(setup.bvh.buildSeconds) << "},\n  \"lightSelection\": {\"mode\": \""
        << setup.lightSelection << "\", \"treeLights\": " << setup.lightTreeLights
        << ", \"treeDepth\": " << setup.lightTreeDepth << ", \"treeBuildSeconds\": "
        << jsonNumber(setup.lightTreeBuildSeconds) << "},\n  \"traversal\": {\"mode\": \""
        << setup.traversal << "\", \"megakernel\": \"bvh\", \"accelerationBytes\": "
        << setup.accelerationBytes << ", \"accelerationBuildSeconds\": "
        << jsonNumber(setup.accelerationBuildSeconds) << "},\n  \"guiding\": {\"on\": "
        << (setup.guiding ? "true" : "false") << ", \"decision\": " << jsonQuoted(setup.guidingText)
        << ", \"trainingSpp\": " << setup.guideTrainingSpp << ", \"trainingSeconds\": "
        << jsonNumber(setup.guideTrainingSeconds) << "},\n  \"runs\": {";
    for (size_t i = 0; i < runs.size(); ++i)
        out << (i ? "," : "") << "\n    " << jsonQuoted(runs[i].kernel) << ": "
            << runJson(runs[i]);
    out << "\n  }";
    if (runs.size() == 2)
        out << ",\n  \"wavefrontOverMegakernel\": "
            << jsonNumber(runs[0].pathsPerSecond() / std::max(runs[1].pathsPerSecond(), 1e-12));
    out << "\n}\n";
    return out.str();
}

} // namespace wf
