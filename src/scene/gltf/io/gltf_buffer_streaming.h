// Buffers go around tinygltf. tinygltf 2.7.0 holds a data: URI's text three times over (the
// JSON string, Buffer::uri, a substring) and decodes it through a fourth copy; it copies a
// GLB's BIN chunk out of the file. For a 5 M-triangle scene that was most of the load's time
// and its peak memory. takeBuffers reads each buffer's bytes once, straight into the array the
// accessors read (base64 decoded from the file's text, an external file read whole, the BIN
// chunk moved in place), and leaves tinygltf a document whose buffers are 4-byte stand-ins;
// returnBuffers puts the bytes into the parsed model.
#pragma once
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace tinygltf {
class Model;
}

namespace wf::gltf {

struct FsPolicy;

struct TakenBuffers {
    // (buffer index, its byteLength bytes), by increasing index.
    std::vector<std::pair<int, std::vector<unsigned char>>> buffers;
};

// `document` is a .gltf's text or a GLB container; it is replaced by what tinygltf should
// parse, and the file's own bytes are released. Buffers this cannot read unambiguously (an
// escaped URI, a media type other than a buffer's, a malformed container) are left in place
// for tinygltf, which refuses or reads them as before. A buffer that cannot be read fails the
// load with one line naming it.
TakenBuffers takeBuffers(std::vector<unsigned char>& document, bool binary, FsPolicy& policy,
                         const std::string& file);

void returnBuffers(tinygltf::Model& model, TakenBuffers& taken, const std::string& file);

// A GLB container: the 8 bytes of magic and version, `json` space-padded as its JSON chunk,
// then `rest` (the chunks after it, headers included) as they are.
std::vector<unsigned char> glbContainer(const unsigned char* magicAndVersion, std::string json,
                                        const unsigned char* rest, std::size_t restSize);

// Strict RFC 4648 base64 (padding only at the end); false on any other character.
bool decodeBase64(const char* text, std::size_t length, std::vector<unsigned char>& out);

} // namespace wf::gltf
