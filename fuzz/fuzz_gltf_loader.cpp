// libFuzzer target for the glTF loader (built with -DWF_FUZZ=ON and clang; see
// fuzz/CMakeLists.txt). Inputs starting with "glTF" load as .glb, others as .gltf, from a
// folder holding a small valid buffer and PNG so URIs have something to find; PNG and JPEG
// inputs also go straight to the image decoder. Inputs of odd length load with every multiply
// placed mesh instanced (--instancing on), so that the instancing path is fuzzed too; even ones
// with the default. Any InputError is the expected outcome for
// bad input; a crash, sanitizer report, leak or timeout is a bug.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "errors.h"
#include "scene/gltf/gltf_images.h"
#include "scene/gltf/gltf_loader.h"

namespace {

std::string scenePath(bool binary) {
    static const std::string folder = [] {
        namespace fs = std::filesystem;
        const fs::path dir = fs::temp_directory_path() / "wf_fuzz_scene";
        fs::create_directories(dir);
        std::ofstream(dir / "data.bin", std::ios::binary) << std::string(64, '\0');
        return dir.string();
    }();
    return folder + (binary ? "/input.glb" : "/input.gltf");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    if (size >= 3 && (data[0] == 0x89 || (data[0] == 0xff && data[1] == 0xd8))) {
        wf::TextureImage image;
        std::string why;
        wf::gltf::decodeImage(data, size, image, why);
    }
    try {
        wf::GltfOptions options;
        options.instancing = size % 2 ? wf::Instancing::On : wf::Instancing::Auto;
        wf::loadGltfFromMemory(data, size, scenePath(binary), options);
    } catch (const wf::InputError&) {
    }
    return 0;
}
