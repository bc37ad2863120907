// What tinygltf may read while it loads a scene: regular files inside the scene's folder, each
// at most 1 GiB and 2 GiB together, and no images decoded (their bytes are kept for
// gltf_images); plus a pre-check that keeps deeply nested JSON away from tinygltf's recursive
// parser.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace tinygltf {
class TinyGLTF;
}

namespace wf::gltf {

// Scene files and the buffers they refer to alike; far above what the GPU buffers hold.
constexpr std::uintmax_t MAX_FILE_BYTES = std::uintmax_t(1) << 30;
// Every external buffer and image of one scene together.
constexpr std::uintmax_t MAX_TOTAL_BYTES = std::uintmax_t(1) << 31;

// The file-system hooks' state: tinygltf keeps only a pointer to it, so it must outlive every
// load made with restrictFileAccess().
struct FsPolicy {
    std::filesystem::path folder; // canonical
    std::string refusal;          // first refused path and why, for the error message
    std::uintmax_t bytesRead = 0; // external files so far, against MAX_TOTAL_BYTES
    // Undecoded bytes of images given by URI (file or data:), by image index. Images in
    // bufferViews are not copied: tinygltf hands them over without checking their range.
    std::map<int, std::vector<unsigned char>> images;
};

// Reads a whole regular file of at most MAX_FILE_BYTES; `error` says why not otherwise.
// The scene file itself is read this way too, so it gets the same size budget.
bool readLimited(const std::filesystem::path& path, std::vector<unsigned char>& out,
                 std::string& error);

// Reads the file a URI (already percent-decoded) names inside policy.folder, under the limits
// above; `error` says why not otherwise.
bool readInFolder(FsPolicy& policy, const std::string& uri, std::vector<unsigned char>& out,
                  std::string& error);

// Installs tinygltf's file-system hooks and image loader: URIs resolve only inside
// policy.folder (no "..", no absolute paths, no symbolic links out), writing is refused, and
// images are accepted undecoded (gltf_images checks and decodes them).
void restrictFileAccess(tinygltf::TinyGLTF& gltf, FsPolicy& policy);

// tinygltf's JSON parser recurses once per nesting level, so a file of a few megabytes of
// "[[[[..." would overflow the stack; glTF itself needs fewer than ten levels.
constexpr int MAX_JSON_DEPTH = 256;
bool nestedTooDeep(const unsigned char* text, std::size_t length);

} // namespace wf::gltf
