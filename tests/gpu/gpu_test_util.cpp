#include "gpu_test_util.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "errors.h"
#include "render/film_error.h"
#include "render/gpu_scene/scene_buffers.h"

namespace wf::test {

Context& gpuContext() {
    static std::unique_ptr<Context> context = [] {
        ContextOptions options;
        options.validation = true;
        options.quiet = true;
        return std::make_unique<Context>(options);
    }();
    return *context;
}

Scene furnaceBox(float albedo, float emission) {
    Scene scene;
    Material material{};
    material.baseColor = glm::vec4(albedo, albedo, albedo, 1.0f);
    material.emission = glm::vec3(emission);
    material.flags = WF_MATERIAL_DOUBLE_SIDED;
    material.roughness = 1.0f;
    material.ior = 1.5f;
    material.specular = 0.0f; // KHR_materials_specular 0: exact Lambert
    material.specularColor = glm::vec3(1.0f);
    scene.materials.push_back(material);
    const std::array<glm::vec3, 8> corners = {
        glm::vec3(-1, -1, -1), glm::vec3(1, -1, -1), glm::vec3(1, 1, -1), glm::vec3(-1, 1, -1),
        glm::vec3(-1, -1, 1),  glm::vec3(1, -1, 1),  glm::vec3(1, 1, 1),  glm::vec3(-1, 1, 1)};
    const int quads[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7},
                             {1, 5, 6, 2}, {3, 2, 6, 7}, {4, 5, 1, 0}};
    for (const auto& q : quads) {
        scene.triangles.push_back({corners[q[0]], 0, corners[q[1]], WF_NO_EMITTER, corners[q[2]], 0});
        scene.triangles.push_back({corners[q[0]], 0, corners[q[2]], WF_NO_EMITTER, corners[q[3]], 0});
    }
    scene.camera.position = glm::vec3(0.1f, -0.05f, 0.2f);
    scene.camera.forward = glm::normalize(glm::vec3(0.3f, 0.2f, -1.0f));
    scene.camera.up = glm::normalize(glm::cross(glm::cross(scene.camera.forward,
                                                           glm::vec3(0, 1, 0)),
                                                scene.camera.forward));
    scene.camera.yfov = 1.2f;
    scene.hasCamera = true;
    return scene;
}

Context* rayTracingContext() {
    static std::unique_ptr<Context> context = []() -> std::unique_ptr<Context> {
        ContextOptions options;
        options.validation = true;
        options.quiet = true;
        options.rayTracing = RayTracingRequest::Required;
        try {
            return std::make_unique<Context>(options);
        } catch (const UsageError&) {
            return nullptr; // no ray-tracing pipelines on this device
        }
    }();
    return context.get();
}

RenderResult renderScene(const Scene& scene, const RenderSettings& settings) {
    return renderScene(scene, settings, gpuContext());
}

RenderResult renderScene(const Scene& scene, const RenderSettings& settings, Context& context) {
    static ShaderCompiler compiler;
    PreparedScene prepared = prepareScene(scene);
    WavefrontRenderer renderer(context, prepared, settings, compiler);
    renderer.render();
    return {renderer.readImage(), renderer.stats(),
            settings.aov ? renderer.readAovs() : AovImages{},
            settings.errorEstimate || settings.aov || settings.pixelList
                ? estimateFilmError(renderer.readMoments(), settings.sampler)
                : ErrorEstimate{}};
}

MeanAndError imageMean(const std::vector<float>& rgb) {
    const size_t n = rgb.size() / 3;
    double sum = 0.0, sumSq = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double v = (rgb[3 * i] + rgb[3 * i + 1] + rgb[3 * i + 2]) / 3.0;
        sum += v;
        sumSq += v * v;
    }
    double mean = sum / n;
    double variance = std::max(0.0, sumSq / n - mean * mean) * n / (n - 1);
    return {mean, std::sqrt(variance / n)};
}

int expectRegionsUnbiased(const std::vector<std::vector<float>>& images,
                          const std::vector<float>& reference,
                          const std::vector<float>& referenceVariance, uint32_t width,
                          uint32_t height, uint32_t block, const std::string& what,
                          const std::vector<bool>* skipRegion) {
    auto regionSum = [&](const std::vector<float>& rgb, uint32_t bx, uint32_t by) {
        double sum = 0.0;
        for (uint32_t y = by * block; y < (by + 1) * block; ++y)
            for (uint32_t x = bx * block; x < (bx + 1) * block; ++x)
                for (int c = 0; c < 3; ++c)
                    sum += rgb[3 * (size_t(y) * width + x) + c];
        return sum;
    };
    const double values = 3.0 * block * block, n = double(images.size());
    int checked = 0;
    for (uint32_t by = 0; by < height / block; ++by)
        for (uint32_t bx = 0; bx < width / block; ++bx) {
            if (skipRegion && (*skipRegion)[by * (width / block) + bx])
                continue;
            double mean = 0.0, meanSq = 0.0;
            for (const auto& image : images) {
                const double m = regionSum(image, bx, by) / values;
                mean += m / n;
                meanSq += m * m / n;
            }
            const double seedError = std::sqrt(std::max(0.0, meanSq - mean * mean) / (n - 1.0));
            const double referenceError = std::sqrt(regionSum(referenceVariance, bx, by)) / values;
            const double expected = regionSum(reference, bx, by) / values;
            EXPECT_NEAR(mean, expected,
                        5.0 * std::hypot(seedError, referenceError) + 2e-3 * expected)
                << what << " region " << bx << "," << by;
            ++checked;
        }
    return checked;
}

} // namespace wf::test
