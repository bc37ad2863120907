// Finds where each buffer's "uri" and "byteLength" values lie in a glTF document's raw JSON,
// without building a DOM, so that gltf_buffer_streaming can take the buffers' bytes out before
// tinygltf copies them. The scan vouches only for what nlohmann/json (tinygltf's parser) would
// read the same way: a document with a top-level "buffers" key written twice or escaped, or a
// buffer whose members are, gives no answer, and such a file is left to tinygltf whole.
#pragma once
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace wf::gltf {

// [begin, end) of one JSON value in the text; a string's span includes its quotes.
struct JsonSpan {
    std::size_t begin = 0;
    std::size_t end = 0;
    bool present() const { return end > begin; }
};

struct BufferMembers {
    JsonSpan uri;         // absent when the buffer has no "uri"
    bool uriEscaped = false; // the string holds a backslash escape: its text is not its value
    JsonSpan byteLength;
};

// One entry per element of the top-level "buffers" array (an empty list without one), or
// nothing when the text is not a JSON object this scan can vouch for.
std::optional<std::vector<BufferMembers>> scanBufferMembers(std::string_view json);

} // namespace wf::gltf
