// wf_gltf_load_check SCENE.gltf|.glb: the scene as `wavefront render` takes it, up to the GPU:
// the loader (at time 0, every animation), the default camera, the BVH build and the light
// tables. Prints one line, "loaded: N triangles, W warnings" with exit code 0, or the refusal
// with exit code 2 (as `wavefront render` would); any other failure exits 1. The glTF-Validator
// corpus test (test_gltf_validator_corpus.py) runs it once per file, so a crash or a hang names
// its file. No Vulkan: it runs in milliseconds, validation layers or not.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "errors.h"
#include "render/gpu_scene/scene_buffers.h"
#include "scene/default_camera.h"
#include "scene/gltf/gltf_loader.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: wf_gltf_load_check SCENE.gltf\n");
        return 2;
    }
    try {
        std::vector<std::string> warnings;
        wf::Scene scene = wf::loadGltf(argv[1], &warnings);
        if (!scene.hasCamera)
            scene.camera = wf::frameBounds(scene);
        const std::size_t triangles = scene.triangles.size();
        const wf::PreparedScene prepared = wf::prepareScene(std::move(scene));
        for (const std::string& line : warnings)
            std::fprintf(stderr, "%s\n", line.c_str());
        std::printf("loaded: %zu triangles (%zu BVH pairs), %zu warnings\n", triangles,
                    prepared.bvhPairs.size(), warnings.size());
        return 0;
    } catch (const wf::InputError& e) {
        std::printf("refused: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::printf("failed: %s\n", e.what());
        return 1;
    }
}
