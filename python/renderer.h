// The C++ half of wavefront.Renderer: one Vulkan context, one shader compiler and the last
// render's pipelines and buffers (reused by the next render of the same scene and settings).
// Options arrive as the CLI's own arguments ("--max-depth", "16": wavefront/__init__.py builds
// them from keywords) and are read by the CLI's functions, so they refuse and render alike.
// Every call takes the renderer's lock with the GIL released; the GIL is taken back only to
// run Python callbacks and to check for Ctrl-C between waves.
#pragma once
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "gpu/context.h"
#include "gpu/shader_compiler.h"
#include "render/gpu_scene/scene_buffers.h"
#include "render/wavefront_renderer.h"
#include "scene/scene_summary.h"

namespace wf::py {

namespace pyb = pybind11;

// A loaded scene: host data only, so any renderer may render it.
struct LoadedScene {
    std::shared_ptr<const PreparedScene> prepared;
    std::string path;
    SceneSummary summary;
    uint64_t id = 0; // tells scenes apart in the renderer's reuse key
};

class Renderer {
public:
    // traversal: "auto", "bvh" or "rt", as --traversal (the context enables ray tracing for
    // rt, and for auto on a GPU that has it).
    Renderer(std::optional<int> device, bool validation, bool quiet,
             const std::string& traversal = "auto");
    ~Renderer();

    // Frees the pipelines, buffers, compiler and device in that order; idempotent.
    void close();
    bool closed() const { return !context_; }
    std::string deviceName() const;
    uint32_t validationMessages() const;

    std::shared_ptr<LoadedScene> load(const std::string& path,
                                      const std::vector<std::string>& flags);
    // A dict: image, aov, spp, seconds, stats (the --json text), width, height.
    pyb::dict render(const LoadedScene& scene, const std::vector<std::string>& flags,
                     const pyb::object& progress);
    // Progressive renders: begin() makes the renderer, advance() adds samples and returns what
    // render() returns; a render between the two ends the progressive one (RuntimeError).
    uint64_t begin(const LoadedScene& scene, const std::vector<std::string>& flags);
    pyb::dict advance(uint64_t session, uint32_t samples);
    // One dict per method, seed and checkpoint, as `wavefront converge` writes its CSV rows.
    pyb::list converge(const LoadedScene& scene, const std::vector<std::string>& flags,
                       const std::vector<std::string>& methods,
                       const std::vector<uint32_t>& seeds, double timeBudget, uint32_t maxSpp,
                       const std::vector<uint32_t>& checkpoints,
                       const std::vector<float>& reference, const pyb::object& progress);

private:
    struct Settings; // flags read into RenderSettings and the rest
    Settings readFlags(const LoadedScene& scene, const std::vector<std::string>& flags) const;
    WavefrontRenderer& rendererFor(const LoadedScene& scene, const Settings& settings);
    pyb::dict output(const LoadedScene& scene, const Settings& settings,
                     std::vector<float> rgb, uint32_t spp, const RenderStats& stats,
                     const std::vector<std::pair<std::string, std::string>>& extraStats,
                     const std::vector<float>* sampleCounts);
    void requireOpen() const;

    std::mutex mutex_;
    std::unique_ptr<Context> context_;
    std::unique_ptr<ShaderCompiler> compiler_;
    // The last render's renderer, kept while the next asks for the same scene and settings.
    std::shared_ptr<const PreparedScene> cachedScene_;
    std::string cachedKey_;
    uint32_t cachedWidth_ = 0, cachedHeight_ = 0; // its image size
    std::unique_ptr<WavefrontRenderer> cached_;
    uint64_t generation_ = 0; // bumped by every render; a progressive session holds its own
    std::shared_ptr<LoadedScene> progressiveScene_;
    std::unique_ptr<Settings> progressiveSettings_;
};

// Every Vulkan device: name, type, driver, subgroup size, API version (wavefront.devices()).
pyb::list listDevices();
// Scene.info: counts, lights, material kinds, bounds, the loader's summary line.
pyb::dict sceneInfo(const LoadedScene& scene);

} // namespace wf::py
