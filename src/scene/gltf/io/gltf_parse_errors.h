// tinygltf's (and its JSON parser's) messages in the project's words: a refusal names the
// object and the rule ("accessor: required member 'componentType' is missing"), never another
// library's wording ("[json.exception...]", "File not found :", "tinygltf:"). Warnings that the
// loader reports itself (images it could not read) are dropped.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace wf::gltf {

// The problem of a file tinygltf refused, from its error text (one or more lines).
std::string parseFailureInOwnWords(const std::string& tinygltfErrors);

// The lines of tinygltf's error text on a model it did load that mean an animation lost a
// channel or sampler: the loader refuses the file for them, as for any broken animation.
std::string droppedByTinygltf(const std::string& tinygltfErrors);
// The other lines (a required member missing that the renderer does not use, such as a
// camera's znear), which the loader passes on as warnings; tinygltf 2.7.0 also calls some
// optional members required ("inverseBindMatrices"), and those lines go.
std::string keptByTinygltf(const std::string& tinygltfErrors);

// tinygltf 2.7.0 refuses some valid glTF: integers written as floats (1.0, 1e0), animation
// channels whose target has no node (KHR_animation_pointer's point elsewhere: ignored), and a
// primitive whose indices accessor has no bufferView (every index 0, so no triangle: skipped),
// an accessor type glTF does not name in a file where nothing reads accessors.
// After a refused parse, the document (`size` bytes of a .gltf or .glb) is mended and the loader
// parses it again. Returns one warning per mend that drops something; `mended` says whether the
// document changed (when not, the refusal stands).
std::vector<std::string> mendForTinygltf(std::vector<unsigned char>& document, std::size_t size,
                                         bool binary, bool& mended);

// tinygltf's warnings (one or more lines) as lines of our own; empty for none.
std::vector<std::string> parseWarningsInOwnWords(const std::string& tinygltfWarnings);

} // namespace wf::gltf
