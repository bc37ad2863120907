#include "app/reports/convergence_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/reports/stats_json.h"
#include "errors.h"
#include "image/atomic_file.h"
#include "image/png_writer.h"

namespace fs = std::filesystem;

namespace wf {
namespace {

void writeText(const std::string& path, const std::string& text) {
    writeFileAtomically(path, [&](const std::string& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        if (!out.flush())
            throw InternalError("cannot write " + path);
    });
}

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

std::string jsonArray(const std::vector<double>& values) {
    std::string text = "[";
    for (size_t i = 0; i < values.size(); ++i)
        text += (i ? ", " : "") + jsonNumber(values[i]);
    return text + "]";
}

} // namespace

void writeConvergenceCsv(const std::string& path, const std::vector<MethodRun>& runs) {
    std::ostringstream csv;
    csv << "method,sampler,light_sampling,seed_index,spp,gpu_seconds,wall_seconds,relmse,mse,"
           "bias,estimated_relmse,estimate_reliable,estimate_upper_bound,integrator\n";
    for (const MethodRun& run : runs) {
        for (size_t s = 0; s < run.perSeed.size(); ++s) {
            for (const Checkpoint& c : run.perSeed[s]) {
                csv << run.method.name << ',' << samplerName(run.method.sampler) << ','
                    << lightSamplingName(run.method.lightSampling) << ',' << s << ',' << c.spp
                    << ',' << format("%.6g", c.gpuSeconds) << ',' << format("%.6g", c.wallSeconds)
                    << ',' << format("%.6g", c.error.relMse) << ',' << format("%.6g", c.error.mse)
                    << ',' << format("%.6g", c.error.bias) << ','
                    << format("%.6g", c.estimate.relMse) << ','
                    << (c.estimate.reliable ? 1 : 0) << ',' << (c.estimate.upperBound ? 1 : 0)
                    << ',' << integratorName(run.method.integrator) << '\n';
            }
        }
    }
    writeText(path, csv.str());
}

std::vector<EqualTimeCrop> writeEqualTimeCrops(const std::string& dir,
                                               const std::vector<MethodRun>& runs,
                                               const std::vector<MethodSummary>& summaries,
                                               const std::vector<float>& reference,
                                               const ConvergenceInfo& info) {
    double budget = INFINITY;
    for (const MethodSummary& s : summaries)
        if (!s.points.empty())
            budget = std::min(budget, s.points.back().gpuSeconds);
    const fs::path folder = fs::path(dir) / "crops";
    fs::create_directories(folder);
    const int x0 = info.crop[0], y0 = info.crop[1], w = info.crop[2], h = info.crop[3];
    auto cropOf = [&](const std::vector<float>& image) {
        std::vector<float> crop;
        for (int y = y0; y < y0 + h; ++y)
            for (int x = x0; x < x0 + w; ++x)
                for (int c = 0; c < 3; ++c)
                    crop.push_back(image[(size_t(y) * info.width + size_t(x)) * 3 + c]);
        return crop;
    };
    std::vector<EqualTimeCrop> crops;
    writePngPreview((folder / "reference.png").string(), w, h, cropOf(reference));
    crops.push_back({"reference", "crops/reference.png", 0, 0.0});
    for (size_t m = 0; m < runs.size(); ++m) {
        const MethodRun& run = runs[m];
        if (run.firstSeedImages.empty())
            continue;
        size_t pick = 0; // the first seed's checkpoint closest to the budget (in log time)
        auto distance = [&](size_t c) {
            return std::abs(std::log(std::max(run.perSeed[0][c].gpuSeconds, 1e-9) / budget));
        };
        for (size_t c = 1; c < run.firstSeedImages.size(); ++c)
            if (distance(c) < distance(pick))
                pick = c;
        const std::string file = "crops/" + run.method.name + ".png";
        writePngPreview((fs::path(dir) / file).string(), w, h, cropOf(run.firstSeedImages[pick]));
        crops.push_back({run.method.name, file, run.checkpoints[pick],
                         run.perSeed[0][pick].gpuSeconds});
    }
    return crops;
}

void writeConvergenceJson(const std::string& path, const ConvergenceInfo& info,
                          const std::vector<MethodRun>& runs,
                          const std::vector<MethodSummary>& summaries,
                          const std::vector<EqualTimeCrop>& crops) {
    std::ostringstream j;
    std::vector<double> seeds(info.seeds.begin(), info.seeds.end());
    j << "{\n  \"scene\": " << jsonQuoted(info.scene) << ",\n  \"device\": "
      << jsonQuoted(info.device) << ",\n  \"traversal\": " << jsonQuoted(info.traversal)
      << ",\n  \"width\": " << info.width << ",\n  \"height\": "
      << info.height << ",\n  \"maxDepth\": " << info.maxDepth << ",\n  \"seeds\": "
      << jsonArray(seeds) << ",\n  \"timeBudgetSeconds\": " << jsonNumber(info.timeBudget)
      << ",\n  \"reference\": {\"file\": " << jsonQuoted(info.reference)
      << ", \"method\": " << jsonQuoted(info.referenceMethod) << ", \"spp\": "
      << info.referenceSpp << ", \"noiseRelMse\": " << jsonNumber(info.referenceNoise)
      << "},\n  \"relMseEpsilon\": " << jsonNumber(kRelMseEpsilon)
      << ",\n  \"target\": " << jsonNumber(info.target) << ",\n  \"methods\": [\n";
    for (size_t m = 0; m < summaries.size(); ++m) {
        const MethodSummary& s = summaries[m];
        std::vector<double> spp, gpu, wall, rel, lessNoise, low, high, mse, bias, estimated,
            reliable;
        for (const CheckpointSummary& p : s.points) {
            spp.push_back(p.spp), gpu.push_back(p.gpuSeconds), wall.push_back(p.wallSeconds);
            rel.push_back(p.relMse), low.push_back(p.relMseLow), high.push_back(p.relMseHigh);
            // The median less a constant is the median of the figures less it.
            lessNoise.push_back(p.relMse - info.referenceNoise);
            mse.push_back(p.mse), bias.push_back(p.bias);
            estimated.push_back(p.estimatedRelMse), reliable.push_back(p.estimateReliable);
        }
        j << "    {\"name\": " << jsonQuoted(s.name) << ", \"sampler\": "
          << jsonQuoted(samplerName(runs[m].method.sampler)) << ", \"lightSampling\": "
          << jsonQuoted(lightSamplingName(runs[m].method.lightSampling)) << ", \"integrator\": "
          << jsonQuoted(integratorName(runs[m].method.integrator))
          << ",\n     \"spp\": " << jsonArray(spp) << ",\n     \"gpuSeconds\": " << jsonArray(gpu)
          << ",\n     \"wallSeconds\": " << jsonArray(wall) << ",\n     \"relMse\": "
          << jsonArray(rel) << ",\n     \"relMseLessReferenceNoise\": " << jsonArray(lessNoise)
          << ",\n     \"relMseQ1\": " << jsonArray(low)
          << ",\n     \"relMseQ3\": " << jsonArray(high) << ",\n     \"mse\": " << jsonArray(mse)
          << ",\n     \"bias\": " << jsonArray(bias) << ",\n     \"estimatedRelMse\": "
          << jsonArray(estimated) << ",\n     \"estimateReliable\": " << jsonArray(reliable)
          << ",\n     \"slopeSpp\": "
          << jsonNumber(s.slopeSpp) << ", \"slopeTime\": " << jsonNumber(s.slopeTime)
          << ", \"timeToTarget\": " << jsonNumber(s.timeToTarget) << ", \"extrapolated\": "
          << (s.extrapolated ? "true" : "false") << "}" << (m + 1 < summaries.size() ? "," : "")
          << "\n";
    }
    j << "  ],\n  \"ranking\": [";
    const std::vector<size_t> order = rankByTimeToTarget(summaries);
    for (size_t i = 0; i < order.size(); ++i)
        j << (i ? ", " : "") << jsonQuoted(summaries[order[i]].name);
    j << "],\n  \"crop\": [" << info.crop[0] << ", " << info.crop[1] << ", " << info.crop[2]
      << ", " << info.crop[3] << "],\n  \"equalTimeCrops\": [\n";
    for (size_t i = 0; i < crops.size(); ++i)
        j << "    {\"method\": " << jsonQuoted(crops[i].method) << ", \"file\": "
          << jsonQuoted(crops[i].file) << ", \"spp\": " << crops[i].spp << ", \"gpuSeconds\": "
          << jsonNumber(crops[i].gpuSeconds) << "}" << (i + 1 < crops.size() ? "," : "") << "\n";
    j << "  ]\n}\n";
    writeText(path, j.str());
}

std::string rankingText(const std::vector<MethodSummary>& summaries, double target) {
    std::ostringstream out;
    out << "ranking by GPU time to relMSE " << format("%.3g", target)
        << " (median over seeds; ~ extrapolated along the fitted slope):\n";
    out << "  #  method                            time to target   slope/spp  slope/time\n";
    const std::vector<size_t> order = rankByTimeToTarget(summaries);
    for (size_t i = 0; i < order.size(); ++i) {
        const MethodSummary& s = summaries[order[i]];
        char line[160];
        std::string time = "never (error not falling)";
        if (std::isfinite(s.timeToTarget))
            time = format(s.extrapolated ? "~%.3g s" : "%.3g s", s.timeToTarget);
        std::snprintf(line, sizeof line, "%3zu  %-32s  %15s  %10.2f  %10.2f\n", i + 1,
                      s.name.c_str(), time.c_str(), s.slopeSpp, s.slopeTime);
        out << line;
    }
    return out.str();
}

} // namespace wf
