// libdraco behind a plain interface, built as its own shared library (wf_draco) that exports
// nothing else: Debian's libdraco carries private copies of tinygltf and stb_image, which must
// not meet the loader's (CMakeLists.txt says how they would). No tinygltf or Draco types here.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace wf::gltf {

// What the glTF accessors say the decoded mesh holds; component types are glTF's codes
// (5120 BYTE .. 5126 FLOAT).
struct DracoRequest {
    struct Attribute {
        std::uint32_t id = 0; // the Draco attribute's unique id
        int componentType = 0;
        int components = 0; // 1 to 4
    };
    std::vector<Attribute> attributes;
    int indexComponentType = 0; // 5121, 5123 or 5125
    std::size_t points = 0;     // every attribute accessor's count
    std::size_t corners = 0;    // the indices accessor's count
};

struct DracoResult {
    // Empty on success; otherwise one line saying what is wrong with the data (the caller
    // names the file and primitive).
    std::string error;
    std::size_t points = 0, corners = 0; // as decoded, also when they mismatch the request
    bool countsMismatch = false;         // then nothing else was converted
    std::vector<unsigned char> indices;  // corners x the index size
    std::vector<std::vector<unsigned char>> attributes; // parallel to request.attributes
};

// Decodes a Draco mesh bitstream and converts its faces and attributes to the requested
// component types. Never throws: hostile data (truncated, lying headers, too large to
// allocate) comes back as an error.
DracoResult decodeDracoMesh(const unsigned char* bytes, std::size_t size,
                            const DracoRequest& request);

} // namespace wf::gltf
