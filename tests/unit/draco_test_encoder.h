// Draco's encoder for the compression tests, in a shared library of its own for the reason
// src/scene/gltf/compression/draco_decoder.h gives (libdraco's private tinygltf and stb_image).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wf::test {

// An indexed triangle mesh: `components` values per vertex in each attribute, floats or
// 16-bit unsigned integers (the latter stored as Draco integers, losslessly).
struct DracoInput {
    struct Attribute {
        bool position = true;        // POSITION, else GENERIC unless one of these:
        bool normal = false;         // NORMAL
        bool texcoord = false;       // TEX_COORD (Draco predicts these from the positions)
        int components = 3;
        std::vector<float> floats;   // either these...
        std::vector<uint16_t> u16;   // ...or these (normalized in glTF's sense)
        int quantizationBits = 0;    // Draco's own quantization of floats; 0: none
    };
    std::vector<Attribute> attributes;
    std::vector<uint32_t> indices;
};

struct DracoOutput {
    std::string error; // empty on success
    std::vector<unsigned char> bytes;
    std::vector<uint32_t> ids; // each attribute's Draco unique id
    std::size_t points = 0, faces = 0; // as encoded (the glTF accessors' counts)
};

// Edgebreaker at Draco's default speed, which reorders points and faces as real files do.
DracoOutput encodeDracoMesh(const DracoInput& input);

} // namespace wf::test
