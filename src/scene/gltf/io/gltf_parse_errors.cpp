// Known tinygltf 2.7.0 and nlohmann::json messages, each rewritten by pattern; anything else
// is kept as the rule it states, with the library's marks (backticks, "[json.exception...]",
// trailing "name = []") taken off.
#include "scene/gltf/io/gltf_parse_errors.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <regex>
#include <sstream>

#include "scene/gltf/io/gltf_buffer_streaming.h"

namespace wf::gltf {

namespace {

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
            line.pop_back();
        // A line may quote a whole data: URI (megabytes), and std::regex recurses per
        // character: the rules read no further than this.
        if (line.size() > 300)
            line.resize(300);
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
        add(R"(.*File not found : data:(.{0,40}).*)",
            "a data: uri ('data:$1...') is not 'data:<media type>;base64,<data>' with a media "
            "type glTF allows");
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
        add(R"(.*Too short data size for glTF Binary.*)",
            "the .glb is shorter than its headers (20 bytes)");
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

using Json = nlohmann::json;

// JSON does not tell 1 from 1.0; tinygltf wants integers for indices, counts and lengths.
bool integralFloatsToIntegers(Json& value) {
    if (value.is_number_float()) {
        const double d = value.get<double>();
        if (!std::isfinite(d) || d != std::floor(d) || std::fabs(d) > 9.0e15)
            return false;
        value = d >= 0.0 ? Json(std::uint64_t(d)) : Json(std::int64_t(d));
        return true;
    }
    bool changed = false;
    if (value.is_array() || value.is_object())
        for (Json& element : value)
            changed |= integralFloatsToIntegers(element);
    return changed;
}

Json* arrayOf(Json& object, const char* key) {
    if (!object.is_object())
        return nullptr;
    const auto found = object.find(key);
    return found != object.end() && found->is_array() ? &*found : nullptr;
}

// Channels without a target node; an animation left without channels goes whole.
bool dropChannelsWithoutNode(Json& doc, std::vector<std::string>& warnings) {
    Json* animations = arrayOf(doc, "animations");
    if (!animations)
        return false;
    bool changed = false;
    for (std::size_t a = animations->size(); a-- > 0;) {
        Json* channels = arrayOf((*animations)[a], "channels");
        if (!channels)
            continue;
        std::size_t dropped = 0;
        for (std::size_t c = channels->size(); c-- > 0;) {
            const Json& target = (*channels)[c].is_object() && (*channels)[c].contains("target")
                                     ? (*channels)[c]["target"]
                                     : Json();
            if (target.is_object() && !target.contains("node")) {
                channels->erase(c);
                ++dropped;
            }
        }
        if (dropped == 0)
            continue;
        changed = true;
        const std::string what = "animation " + std::to_string(a) + ": " +
                                 std::to_string(dropped) +
                                 " channel(s) target no node (KHR_animation_pointer or another "
                                 "extension's targets, not supported)";
        if (channels->empty()) {
            animations->erase(a);
            warnings.push_back(what + "; the animation is ignored");
        } else {
            warnings.push_back(what + "; they are ignored");
        }
    }
    return changed;
}

// A primitive whose indices accessor has neither bufferView nor sparse values indexes vertex 0
// only: every triangle degenerate, nothing to draw.
bool dropPrimitivesWithZeroIndices(Json& doc, std::vector<std::string>& warnings) {
    Json* meshes = arrayOf(doc, "meshes");
    Json* accessors = arrayOf(doc, "accessors");
    if (!meshes || !accessors)
        return false;
    bool changed = false;
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        Json* primitives = arrayOf((*meshes)[m], "primitives");
        for (std::size_t p = primitives ? primitives->size() : 0; p-- > 0;) {
            const Json& primitive = (*primitives)[p];
            if (!primitive.is_object() || !primitive.contains("indices") ||
                !primitive["indices"].is_number_unsigned())
                continue;
            const std::uint64_t i = primitive["indices"].get<std::uint64_t>();
            if (i >= accessors->size() || !(*accessors)[i].is_object() ||
                (*accessors)[i].contains("bufferView") || (*accessors)[i].contains("sparse"))
                continue;
            primitives->erase(p);
            changed = true;
            warnings.push_back("mesh " + std::to_string(m) + " primitive " + std::to_string(p) +
                               ": its indices accessor " + std::to_string(i) +
                               " has no bufferView (every index 0, no triangle); skipped");
        }
    }
    return changed;
}

// An accessor type glTF does not name (the validator warns) is harmless where nothing reads
// accessors at all: no meshes, animations or skins. Elsewhere the refusal stands.
bool retypeUnreadAccessors(Json& doc, std::vector<std::string>& warnings) {
    Json* accessors = arrayOf(doc, "accessors");
    for (const char* reader : {"meshes", "animations", "skins"})
        if (Json* readers = arrayOf(doc, reader); readers && !readers->empty())
            return false;
    if (!accessors)
        return false;
    bool changed = false;
    for (std::size_t a = 0; a < accessors->size(); ++a) {
        Json& accessor = (*accessors)[a];
        if (!accessor.is_object() || !accessor.contains("type") || !accessor["type"].is_string())
            continue;
        const std::string type = accessor["type"].get<std::string>();
        if (type == "SCALAR" || type == "VEC2" || type == "VEC3" || type == "VEC4" ||
            type == "MAT2" || type == "MAT3" || type == "MAT4")
            continue;
        accessor["type"] = "SCALAR";
        changed = true;
        warnings.push_back("accessor " + std::to_string(a) + ": type '" + type.substr(0, 40) +
                           "' is not glTF's; nothing reads it");
    }
    return changed;
}

} // namespace

std::vector<std::string> mendForTinygltf(std::vector<unsigned char>& document, std::size_t size,
                                         bool binary, bool& mended) {
    mended = false;
    std::size_t jsonStart = 0, jsonLength = size;
    if (binary) {
        std::uint32_t chunkLength = 0;
        if (size < 20 || std::memcmp(document.data() + 16, "JSON", 4) != 0)
            return {};
        std::memcpy(&chunkLength, document.data() + 12, 4);
        if (chunkLength > size - 20)
            return {};
        jsonStart = 20;
        jsonLength = chunkLength;
    }
    const unsigned char* text = document.data() + jsonStart;
    Json doc = Json::parse(text, text + jsonLength, nullptr, false);
    if (!doc.is_object())
        return {};
    std::vector<std::string> warnings;
    mended |= integralFloatsToIntegers(doc);
    mended |= dropChannelsWithoutNode(doc, warnings);
    mended |= dropPrimitivesWithZeroIndices(doc, warnings);
    mended |= retypeUnreadAccessors(doc, warnings);
    if (!mended)
        return {};
    std::string json = doc.dump(-1, ' ', false, Json::error_handler_t::replace);
    if (!binary) {
        document.assign(json.begin(), json.end());
    } else {
        const std::size_t restStart = jsonStart + jsonLength;
        document = glbContainer(document.data(), std::move(json), document.data() + restStart,
                                size - restStart);
    }
    return warnings;
}

std::string parseFailureInOwnWords(const std::string& tinygltfErrors) {
    const std::vector<std::string> all = lines(tinygltfErrors);
    if (all.empty())
        return "the parser refused the file without naming the rule it breaks";
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
