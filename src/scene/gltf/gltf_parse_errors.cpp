// Known tinygltf 2.7.0 and nlohmann::json messages, each rewritten by pattern; anything else
// is kept as the rule it states, with the library's marks (backticks, "[json.exception...]",
// trailing "name = []") taken off.
#include "scene/gltf/gltf_parse_errors.h"

#include <regex>
#include <sstream>

namespace wf::gltf {

namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
        if (!line.empty())
            out.push_back(line);
    }
    return out;
}

std::string cleaned(std::string text) {
    text = std::regex_replace(text, std::regex(R"(\[json\.exception\.[a-z_]+\.\d+\]\s*)"), "");
    text = std::regex_replace(text, std::regex(R"(\s*name\s*=\s*\[[^\]]*\])"), "");
    text = std::regex_replace(text, std::regex("[`]"), "'");
    text = std::regex_replace(text, std::regex("''"), "'");
    while (!text.empty() && (text.back() == '.' || text.back() == ' '))
        text.pop_back();
    return text;
}

struct Rule {
    std::regex pattern;
    std::string replacement; // $1.. from the pattern
};

const std::vector<Rule>& rules() {
    static const std::vector<Rule> table = [] {
        std::vector<Rule> r;
        auto add = [&](const char* pattern, const char* replacement) {
            r.push_back({std::regex(pattern), replacement});
        };
        add(R"(.*parse error at line (\d+), column (\d+).*)",
            "is not valid JSON (a syntax error at line $1, column $2)");
        add(R"(.*number overflow parsing '([^']*)'.*)",
            "its JSON holds the number $1, which no double can hold");
        add(R"(.*type_error.*|.*type must be.*)", "its JSON has a value of the wrong type");
        add(R"(.*'uri' is missing from non binary glTF file buffer.*)",
            "a buffer has no uri (only the first buffer of a .glb may omit it)");
        add(R"(.*File not found : (.*))", "cannot read '$1': not found");
        add(R"(.*Failed to load external 'uri' for buffer\[(\d+)\].*)",
            "buffer $1: its file could not be read");
        add(R"(.*'(\w+)' property is missing in (\w+).*)",
            "$2: the required member '$1' is missing");
        add(R"(.*'(\w+)' property is missing.*)", "the required member '$1' is missing");
        add(R"(.*[`'](\w+)[`'] field is missing in ([\w.]+).*)",
            "$2: the required member '$1' is missing");
        add(R"(.*[`'](\w+)' does not contain an JSON object.*)",
            "'$1' must be an array of objects");
        add(R"(.*Invalid [`']componentType[`'] in accessor\. Got (-?\d+).*)",
            "an accessor's componentType $1 is not one of glTF's");
        add(R"re(.*Unsupported [`']type[`'] for accessor object\. Got "?([^"]*)"?.*)re",
            "an accessor's type '$1' is not SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 or MAT4");
        add(R"re(.*Invalid camera type: "?([^"]*)"?.*)re",
            "a camera's type '$1' is not perspective or orthographic");
        add(R"(.*Perspective camera description not found.*)",
            "a perspective camera has no 'perspective' object");
        add(R"(.*Orthographic camera description not found.*)",
            "an orthographic camera has no 'orthographic' object");
        add(R"(.*JSON string too short.*)", "the file is empty or too short to be glTF");
        add(R"(.*Invalid glTF binary.*|.*Invalid glTF.*chunk.*)",
            "not a valid binary glTF file (its header or chunks are broken)");
        add(R"(.*Spot light description not found.*)", "a spot light has no 'spot' object");
        add(R"(.*Invalid [`']byteStride' value.*)",
            "a bufferView's byteStride is not a multiple of 4 from 4 to 252");
        add(R"(.*Invalid [`']byteLength'\. Must be equal or less than binary size.*)",
            "a buffer's byteLength is more than the .glb's BIN chunk holds");
        add(R"(.*Invalid binary data in [`']Buffer', or GLB with empty BIN chunk.*)",
            "a buffer's data is missing (or the .glb's BIN chunk is empty)");
        add(R"(.*[Ii]nvalid magic.*)", "not a binary glTF file (no 'glTF' magic)");
        add(R"(.*Neither required [`']bufferView[`'] nor [`']uri[`'] defined for image\[(\d+)\].*)",
            "image $1 has neither a bufferView nor a uri");
        add(R"(.*primitive indices accessor out of bounds.*)",
            "a primitive's indices accessor does not exist");
        add(R"(.*Failed to decode 'uri'.*)", "a data: uri is not valid base64");
        add(R"(.*Invalid file size.*|.*File size mismatch.*)",
            "the .glb's length disagrees with its header");
        return r;
    }();
    return table;
}

std::string translated(const std::string& line) {
    for (const Rule& rule : rules()) {
        std::smatch m;
        if (std::regex_match(line, m, rule.pattern))
            return m.format(rule.replacement);
    }
    return cleaned(line);
}

// tinygltf reports an external image it could not read twice over; the image loader says it
// once, naming the image and what shows instead.
bool reportedByTheLoader(const std::string& line) {
    return line.find("for image[") != std::string::npos ||
           (line.find("File not found") != std::string::npos &&
            line.find("buffer") == std::string::npos);
}

} // namespace

std::string parseFailureInOwnWords(const std::string& tinygltfErrors) {
    const std::vector<std::string> all = lines(tinygltfErrors);
    if (all.empty())
        return "cannot parse glTF";
    // The first line is the cause; tinygltf's later lines repeat it in general terms.
    std::string out = translated(all.front());
    for (size_t i = 1; i < all.size() && out.size() < 200; ++i) {
        const std::string more = translated(all[i]);
        if (more != out && out.find(more) == std::string::npos &&
            all[i].find("Failed to load external") == std::string::npos &&
            all[i].find("File not found") == std::string::npos)
            out += "; " + more;
    }
    return out;
}

std::string droppedByTinygltf(const std::string& tinygltfErrors) {
    std::string out;
    for (const std::string& line : lines(tinygltfErrors))
        if (line.find("animation") != std::string::npos)
            out += line + "\n";
    return out;
}

std::string keptByTinygltf(const std::string& tinygltfErrors) {
    std::string out;
    for (const std::string& line : lines(tinygltfErrors))
        if (line.find("animation") == std::string::npos &&
            line.find("'inverseBindMatrices' property is missing") == std::string::npos)
            out += line + "\n";
    return out;
}

std::vector<std::string> parseWarningsInOwnWords(const std::string& tinygltfWarnings) {
    std::vector<std::string> out;
    for (const std::string& line : lines(tinygltfWarnings))
        if (!reportedByTheLoader(line))
            out.push_back(translated(line));
    return out;
}

} // namespace wf::gltf
