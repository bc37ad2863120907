// Reads vertex positions and indices out of a parsed glTF model. tinygltf 2.7.0 checks few of
// the indices, offsets, strides and counts it parses, so every one is checked here against the
// model's arrays and buffer sizes before a byte is read.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/vec3.hpp>

namespace tinygltf {
class Model;
}

namespace wf::gltf {

// Every problem in a scene file becomes one InputError("<file>: <problem>"); the loader and the
// accessor reader share these so their messages read alike.
[[noreturn]] void fail(const std::string& file, const std::string& problem);
// Fails unless 0 <= index < size; `by` names what holds the index, `what` what it points at.
void checkIndex(const std::string& file, int index, std::size_t size, const std::string& what,
                const std::string& by);

// Holds the model and file name by reference: both must outlive the reader.
class AccessorReader {
public:
    AccessorReader(const tinygltf::Model& model, const std::string& file)
        : model_(model), file_(file) {}

    // Float VEC3 positions, all finite. Meshes instanced by many nodes share one accessor, so
    // each is read once; the reference stays valid for the reader's lifetime.
    const std::vector<glm::vec3>& positions(int accessor, const std::string& where);
    // u8/u16/u32 indices widened to u32, each below vertexCount.
    std::vector<std::uint32_t> indices(int accessor, std::size_t vertexCount,
                                       const std::string& where);

private:
    struct Elements;
    Elements elements(int index, const std::string& role, int type) const;

    const tinygltf::Model& model_;
    const std::string& file_;
    std::unordered_map<int, std::vector<glm::vec3>> positionCache_;
};

} // namespace wf::gltf
