// tinygltf's (and its JSON parser's) messages in the project's words: a refusal names the
// object and the rule ("accessor: required member 'componentType' is missing"), never another
// library's wording ("[json.exception...]", "File not found :", "tinygltf:"). Warnings that the
// loader reports itself (images it could not read) are dropped.
#pragma once
#include <string>
#include <vector>

namespace wf::gltf {

// The problem of a file tinygltf refused, from its error text (one or more lines).
std::string parseFailureInOwnWords(const std::string& tinygltfErrors);

// The lines of tinygltf's error text on a model it did load that mean something was dropped
// (an animation channel without its sampler): the loader refuses the file for them. tinygltf
// 2.7.0 also calls some optional members required ("inverseBindMatrices"); those lines go.
std::string droppedByTinygltf(const std::string& tinygltfErrors);

// tinygltf's warnings (one or more lines) as lines of our own; empty for none.
std::vector<std::string> parseWarningsInOwnWords(const std::string& tinygltfWarnings);

} // namespace wf::gltf
