#pragma once
// tinygltf and the JSON library it parses with report problems in their own words
// ("File not found : ", "[json.exception.out_of_range.406] ..."); a refusal should name the
// object and the rule in the project's words instead.
#include <string>

namespace wf::gltf {

// Rewords each line of a parser's error or warning text and joins them with "; ". A line of a
// form it does not know keeps its words, without the library's prefixes.
std::string rewordParserMessages(const std::string& text);

} // namespace wf::gltf
