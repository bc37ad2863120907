#include "scene/gltf/gltf_parse_messages.h"

#include <regex>
#include <vector>

namespace wf::gltf {
namespace {

struct Rewording {
    std::regex pattern;
    const char* replacement; // std::regex_replace format: $1, $2 ...
};

const std::vector<Rewording>& rewordings() {
    // The forms tinygltf 2.7 and nlohmann::json 3.11 write (Debian 12's packages), most
    // specific first; the first that matches a whole line wins.
    static const std::vector<Rewording> table = [] {
        auto rule = [](const char* pattern, const char* replacement) {
            return Rewording{std::regex(pattern), replacement};
        };
        return std::vector<Rewording>{
            rule(R"(\[json\.exception\.out_of_range\.406\] number overflow parsing '(.*)')",
                 "the number $1 is beyond what a 64-bit float holds (JSON numbers must be finite)"),
            rule(R"(\[json\.exception\.parse_error\.\d+\] parse error at (line \d+, column \d+): syntax error while parsing (.*?) - (.*))",
                 "the JSON is malformed at $1, in $2: $3"),
            rule(R"(\[json\.exception\.parse_error\.\d+\] parse error(?: at (.*?))?: (.*))",
                 "the JSON is malformed ($1): $2"),
            rule(R"(\[json\.exception\.[a-z_]+\.\d+\] (.*))", "the JSON cannot be read: $1"),
            rule(R"('uri' is missing from non binary glTF file buffer\.?)",
                 "a buffer has no 'uri' (in a .gltf every buffer needs one; only a .glb's "
                 "first buffer may leave it out)"),
            rule(R"(File not found : data:(.{0,40}).*)",
                 "a data URI cannot be decoded ('data:$1...'; glTF wants "
                 "'data:<media type>;base64,<data>' with a media type it allows)"),
            rule(R"(File not found : (.+))",
                 "'$1' cannot be read (missing, or outside the scene's folder)"),
            // With no name: the missing 'uri' above, said already.
            rule(R"(File not found :)", ""),
            // gltf_images says what becomes of the image.
            rule(R"(Failed to load external 'uri' for image\[(\d+)\] name = \[(.*)\])", ""),
            rule(R"(Failed to decode 'uri' for image\[(\d+)\].*)",
                 "image $1's data URI cannot be decoded"),
            rule(R"(Failed to decode 'uri' : (.{0,40}).*)", "a data URI cannot be decoded ('$1...')"),
            rule(R"(Neither required `bufferView` nor `uri` defined for image\[(\d+)\].*)",
                 "image $1 has neither a 'uri' nor a 'bufferView'"),
            rule(R"(Failed to parse `(uri|bufferView)` for image\[(\d+)\].*)",
                 "image $2's '$1' is not valid"),
            rule(R"(File read error : .*data:image/webp.* : (.*))", "$1"),
            rule(R"(File read error : (.*) : (.*))", "'$1' cannot be read: $2"),
            rule(R"(File is empty : (.*))", "'$1' is empty"),
            rule(R"(File open error : (.*))", "'$1' cannot be opened"),
            rule(R"(Invalid file size : (.*))", "'$1' has a size that cannot be read"),
            rule(R"(Invalid binary data in `Buffer', or GLB with empty BIN chunk\.?)",
                 "a buffer's binary data is missing (or the GLB's BIN chunk is empty)"),
            rule(R"(`(\w+)' does not contain an JSON object\.?)", "'$1' must be an array of objects"),
            rule(R"(`(\w+)` field is missing in (.*?)\.?)", "'$1' is missing in $2"),
            rule(R"('(\w+)' property is missing in `(\w+)'\.?)", "required property '$1' is missing in $2"),
            rule(R"('(\w+)' property is missing in (\w+)\.?)", "required property '$1' is missing in $2"),
            rule(R"('(\w+)' property is missing\.?)", "required property '$1' is missing"),
            rule(R"('(\w+)' property is not (an? [\w ]+?)( type)?\.?)", "property '$1' must be $2"),
            rule(R"(Invalid glTF binary\.?)",
                 "not a valid GLB (its header's version or length, or a chunk's length, is wrong)"),
            rule(R"(Too short data size for glTF Binary\.?)",
                 "the GLB is shorter than its headers (20 bytes)"),
            rule(R"(JSON string too short\.?)", "the JSON is empty or too short to hold an object"),
            rule(R"(Invalid type for chunk1 data\.?)", "the GLB's second chunk is not a BIN chunk"),
            rule(R"("asset" object not found.*)", "required object 'asset' is missing"),
            rule(R"((\w+)\[(\d+)\] is not a JSON object\.?)", "$1 $2 must be an object"),
            rule(R"re(image\[(\d+)\] bufferView "(\d+)" not found in the scene\.?)re",
                 "image $1 refers to bufferView $2, which does not exist"),
            rule(R"(accessor\[(\d+)\] invalid bufferView)",
                 "accessor $1 refers to a bufferView that does not exist"),
            rule(R"re(Unsupported `type` for accessor object\. Got "(.*)")re",
                 "an accessor's type \"$1\" is none of SCALAR, VEC2-4, MAT2-4"),
            rule(R"(Spot light description not found\.?)", "a spot light has no 'spot' object"),
            rule(R"(Invalid `byteStride' value\. `byteStride' must be the multiple of 4 : (\d+))",
                 "a bufferView's byteStride ($1) is not a multiple of 4"),
            rule(R"(Invalid `byteLength'\. Must be equal or less than binary size: `byteLength' = (\d+), binary size = (\d+))",
                 "a buffer's byteLength ($1) is more than its data ($2 bytes)"),
            rule(R"(primitive indices accessor out of bounds)",
                 "a primitive's indices accessor is out of range"),
        };
    }();
    return table;
}

std::string rewordLine(const std::string& line) {
    for (const Rewording& rewording : rewordings()) {
        if (std::regex_match(line, rewording.pattern)) {
            return std::regex_replace(line, rewording.pattern, rewording.replacement,
                                      std::regex_constants::format_first_only);
        }
    }
    return line;
}

} // namespace

std::string rewordParserMessages(const std::string& text) {
    // A line may quote a whole data: URI (megabytes); std::regex recurses per character.
    constexpr size_t MAX_LINE_CHARS = 300, MAX_CHARS = 400;
    std::string out, line;
    auto flush = [&] {
        size_t first = line.find_first_not_of(" \t");
        size_t last = line.find_last_not_of(" \t;");
        if (first != std::string::npos) {
            std::string reworded = rewordLine(line.substr(first, last - first + 1));
            if (!reworded.empty() && out.find(reworded) == std::string::npos) { // repeats
                out += (out.empty() ? "" : "; ") + reworded;
            }
        }
        line.clear();
    };
    for (char c : text) {
        if (c == '\n' || c == '\r') {
            flush();
        } else if (line.size() < MAX_LINE_CHARS) {
            line += c;
        }
    }
    flush();
    if (out.size() > MAX_CHARS) {
        out = out.substr(0, MAX_CHARS) + "...";
    }
    return out;
}

} // namespace wf::gltf
