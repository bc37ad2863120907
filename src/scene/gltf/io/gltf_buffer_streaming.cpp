#include "scene/gltf/io/gltf_buffer_streaming.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/io/gltf_file_access.h"
#include "scene/gltf/io/gltf_json_scan.h"

namespace wf::gltf {
namespace {

// tinygltf checks a data: URI's length against byteLength, so the stand-in is 4 real bytes.
constexpr std::string_view STAND_IN_URI = "\"data:application/octet-stream;base64,AAAAAA==\"";
constexpr std::string_view STAND_IN_LENGTH = "4";
// A buffer without uri (and not a .glb's BIN chunk) gets the stand-in's uri after its length.
constexpr std::string_view STAND_IN_LENGTH_AND_URI =
    "4,\"uri\":\"data:application/octet-stream;base64,AAAAAA==\"";
// The media types glTF gives a buffer's data URI; tinygltf takes image ones too, so those stay
// with it.
constexpr std::array<std::string_view, 2> BUFFER_MEDIA_TYPES = {"application/octet-stream",
                                                                "application/gltf-buffer"};

// RFC 2397: data:[<media type>][;<parameter>...][;base64],<data>. Whether the URI is a
// buffer's (one of glTF's media types) and, if so, whether its data is base64 (else
// percent-encoded bytes).
std::optional<bool> bufferDataUriIsBase64(std::string_view uri) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string_view::npos) {
        return std::nullopt;
    }
    std::string_view header = uri.substr(5, comma - 5); // after "data:"
    const std::string_view type = header.substr(0, header.find(';'));
    if (std::find(BUFFER_MEDIA_TYPES.begin(), BUFFER_MEDIA_TYPES.end(), type) ==
        BUFFER_MEDIA_TYPES.end()) {
        return std::nullopt;
    }
    constexpr std::string_view BASE64 = ";base64";
    const bool base64 = header.size() >= BASE64.size() &&
                        header.substr(header.size() - BASE64.size()) == BASE64;
    header = header.substr(type.size(),
                           header.size() - type.size() - (base64 ? BASE64.size() : 0));
    // What lies between is ";attribute=value" parameters, each non-empty.
    while (!header.empty()) {
        const std::size_t next = header.find(';', 1);
        const std::string_view parameter =
            header.substr(1, next == header.npos ? header.npos : next - 1);
        if (header[0] != ';' || parameter.find('=') == parameter.npos || parameter.front() == '=') {
            return std::nullopt;
        }
        header = next == header.npos ? std::string_view() : header.substr(next);
    }
    return base64;
}

// Where a GLB's chunks lie, when the container passes every check tinygltf makes (else the
// file is left to tinygltf, which refuses it in its own words).
struct GlbLayout {
    std::size_t jsonStart = 20, jsonLength = 0;
    std::size_t binStart = 0, binLength = 0; // binLength 0: no BIN chunk
};

std::uint32_t word(const std::vector<unsigned char>& bytes, std::size_t at) {
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
}

std::optional<GlbLayout> glbLayout(const std::vector<unsigned char>& bytes) {
    if (bytes.size() < 20 || word(bytes, 8) != bytes.size() ||
        std::memcmp(bytes.data() + 16, "JSON", 4) != 0) {
        return std::nullopt;
    }
    GlbLayout glb;
    glb.jsonLength = word(bytes, 12);
    const std::size_t jsonEnd = 20 + glb.jsonLength;
    if (glb.jsonLength == 0 || jsonEnd > bytes.size() || jsonEnd % 4 != 0) {
        return std::nullopt;
    }
    if (jsonEnd == bytes.size()) {
        return glb;
    }
    if (bytes.size() - jsonEnd < 12 || std::memcmp(bytes.data() + jsonEnd + 4, "BIN\0", 4) != 0) {
        return std::nullopt;
    }
    glb.binStart = jsonEnd + 8;
    glb.binLength = word(bytes, jsonEnd);
    if (glb.binLength < 4 || glb.binLength % 4 != 0 ||
        glb.binLength > bytes.size() - glb.binStart) {
        return std::nullopt;
    }
    return glb;
}

std::optional<std::size_t> plainUnsigned(std::string_view digits) {
    if (digits.empty() || digits.size() > 13) { // 10^13 is far past any buffer's 1 GiB
        return std::nullopt;
    }
    std::size_t value = 0;
    for (char c : digits) {
        if (c < '0' || c > '9') {
            return std::nullopt;
        }
        value = value * 10 + std::size_t(c - '0');
    }
    return value;
}

// RFC 3986 percent-decoding of a relative URI.
std::optional<std::string> percentDecoded(std::string_view uri) {
    const auto hex = [](char c) -> int {
        return c >= '0' && c <= '9'   ? c - '0'
               : c >= 'a' && c <= 'f' ? c - 'a' + 10
               : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                      : -1;
    };
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        if (i + 2 >= uri.size() || hex(uri[i + 1]) < 0 || hex(uri[i + 2]) < 0) {
            return std::nullopt;
        }
        out += char(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
        i += 2;
    }
    return out;
}

// NoData: a buffer without uri that is not a .glb's BIN chunk (glTF allows one, for extensions
// to fill); it is kept empty, so any accessor or image that reads it is refused by name.
enum class Source { DataUri, File, BinChunk, NoData };

struct Take {
    int buffer = 0;
    Source source = Source::File;
    std::size_t byteLength = 0;
    BufferMembers members;
    bool base64 = true; // a DataUri's encoding: base64, else percent-encoded (RFC 2397)
};

// Decides for every buffer, before a byte is read; nothing when any buffer is unclear, since
// a buffer tinygltf reads must still find the BIN chunk it may refer to.
std::optional<std::vector<Take>> planTakes(std::string_view json,
                                           const std::vector<BufferMembers>& buffers,
                                           bool binary, bool hasBin) {
    std::vector<Take> takes;
    for (std::size_t b = 0; b < buffers.size(); ++b) {
        const BufferMembers& members = buffers[b];
        const std::optional<std::size_t> byteLength = plainUnsigned(
            json.substr(members.byteLength.begin, members.byteLength.end - members.byteLength.begin));
        if (!byteLength || *byteLength == 0 || b > std::size_t(INT32_MAX)) {
            return std::nullopt;
        }
        Take take{int(b), Source::File, *byteLength, members};
        if (!members.uri.present()) {
            // Only buffer 0 may be the BIN chunk; tinygltf gives it to any buffer without uri.
            // A .glb without one whose buffer 0 has no uri is left to tinygltf, which refuses it.
            if (b == 0 && binary && !hasBin) {
                return std::nullopt;
            }
            take.source = b == 0 && hasBin ? Source::BinChunk : Source::NoData;
        } else {
            const std::string_view uri =
                json.substr(members.uri.begin + 1, members.uri.end - members.uri.begin - 2);
            if (members.uriEscaped) {
                return std::nullopt;
            }
            if (uri.rfind("data:", 0) == 0) {
                const std::optional<bool> base64 = bufferDataUriIsBase64(uri);
                if (!base64) {
                    return std::nullopt;
                }
                take.source = Source::DataUri;
                take.base64 = *base64;
            }
        }
        takes.push_back(take);
    }
    return takes;
}

std::vector<unsigned char> readTake(const Take& take, std::string_view json, FsPolicy& policy,
                                    const std::string& file) {
    const std::string name = "buffer " + std::to_string(take.buffer);
    const std::string_view uri =
        json.substr(take.members.uri.begin + 1, take.members.uri.end - take.members.uri.begin - 2);
    std::vector<unsigned char> bytes;
    std::string what;
    if (take.source == Source::NoData) {
        return bytes;
    }
    if (take.source == Source::DataUri) {
        const std::size_t comma = uri.find(',') + 1;
        if (take.base64 && !decodeBase64(uri.data() + comma, uri.size() - comma, bytes)) {
            fail(file, name + ": its data URI is not valid base64");
        }
        if (!take.base64) {
            const std::optional<std::string> data = percentDecoded(uri.substr(comma));
            if (!data) {
                fail(file, name + ": its data URI has a malformed %-escape");
            }
            bytes.assign(data->begin(), data->end());
        }
        what = "its data URI";
    } else {
        const std::optional<std::string> path = percentDecoded(uri);
        std::string why = "a malformed %-escape";
        if (!path || !readInFolder(policy, *path, bytes, why)) {
            const bool named = why.rfind("refused to read", 0) == 0; // names the path itself
            fail(file, name + ": " + (named ? "" : "cannot read '" + std::string(uri) + "': ") + why);
        }
        what = "'" + *path + "'";
    }
    if (bytes.size() < take.byteLength) {
        fail(file, name + ": " + what + " holds " + std::to_string(bytes.size()) +
                       " bytes, fewer than its byteLength " + std::to_string(take.byteLength));
    }
    bytes.resize(take.byteLength);
    bytes.shrink_to_fit(); // a no-op unless the source was padded
    return bytes;
}

// The document with each taken buffer's uri and byteLength replaced by the stand-in's.
std::string standInJson(std::string_view json, const std::vector<Take>& takes) {
    std::vector<std::pair<JsonSpan, std::string_view>> edits;
    for (const Take& take : takes) {
        if (take.members.uri.present()) {
            edits.push_back({take.members.uri, STAND_IN_URI});
        }
        edits.push_back({take.members.byteLength, take.source == Source::NoData
                                                      ? STAND_IN_LENGTH_AND_URI
                                                      : STAND_IN_LENGTH});
    }
    std::sort(edits.begin(), edits.end(),
              [](const auto& a, const auto& b) { return a.first.begin < b.first.begin; });
    std::string out;
    std::size_t copied = 0;
    for (const auto& [span, replacement] : edits) {
        out.append(json.substr(copied, span.begin - copied));
        out.append(replacement);
        copied = span.end;
    }
    out.append(json.substr(copied));
    return out;
}

// A GLB of the stand-in JSON and, when buffers came from it, a 4-byte BIN chunk.
std::vector<unsigned char> standInGlb(const std::vector<unsigned char>& original, std::string json,
                                      bool withBin) {
    const unsigned char bin[12] = {4, 0, 0, 0, 'B', 'I', 'N', '\0', 0, 0, 0, 0};
    return glbContainer(original.data(), std::move(json), bin, withBin ? sizeof bin : 0);
}

} // namespace

std::vector<unsigned char> glbContainer(const unsigned char* magicAndVersion, std::string json,
                                        const unsigned char* rest, std::size_t restSize) {
    json.append((4 - json.size() % 4) % 4, ' '); // GLB chunks are 4-byte aligned
    const std::uint32_t total = std::uint32_t(20 + json.size() + restSize);
    const std::uint32_t jsonChunk = std::uint32_t(json.size());
    std::vector<unsigned char> glb(total);
    std::memcpy(glb.data(), magicAndVersion, 8);
    std::memcpy(glb.data() + 8, &total, 4);
    std::memcpy(glb.data() + 12, &jsonChunk, 4);
    std::memcpy(glb.data() + 16, "JSON", 4);
    std::memcpy(glb.data() + 20, json.data(), json.size());
    if (restSize > 0)
        std::memcpy(glb.data() + 20 + json.size(), rest, restSize);
    return glb;
}

bool decodeBase64(const char* text, std::size_t length, std::vector<unsigned char>& out) {
    static const std::array<std::int8_t, 256> sextets = [] {
        std::array<std::int8_t, 256> table{};
        table.fill(-1);
        const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        for (int i = 0; i < 64; ++i) {
            table[static_cast<unsigned char>(alphabet[i])] = std::int8_t(i);
        }
        return table;
    }();
    std::size_t padding = 0;
    while (padding < 2 && length > padding && text[length - 1 - padding] == '=') {
        ++padding;
    }
    const std::size_t digits = length - padding;
    if (digits % 4 == 1 || (padding > 0 && length % 4 != 0)) {
        return false;
    }
    out.resize(digits / 4 * 3 + (digits % 4 == 0 ? 0 : digits % 4 - 1));
    const auto* in = reinterpret_cast<const unsigned char*>(text);
    unsigned char* to = out.data();
    std::uint32_t invalid = 0; // any -1 sextet sets the sign bit
    std::size_t i = 0;
    for (; i + 4 <= digits; i += 4) {
        const std::int32_t a = sextets[in[i]], b = sextets[in[i + 1]], c = sextets[in[i + 2]],
                           d = sextets[in[i + 3]];
        invalid |= std::uint32_t(a | b | c | d);
        const std::uint32_t group = std::uint32_t(a) << 18 | std::uint32_t(b) << 12 |
                                    std::uint32_t(c) << 6 | std::uint32_t(d);
        *to++ = static_cast<unsigned char>(group >> 16);
        *to++ = static_cast<unsigned char>(group >> 8);
        *to++ = static_cast<unsigned char>(group);
    }
    if (i < digits) { // 2 or 3 digits: 1 or 2 bytes
        std::uint32_t group = 0;
        for (std::size_t k = 0; k < 4; ++k) {
            const std::int32_t s = i + k < digits ? sextets[in[i + k]] : 0;
            invalid |= std::uint32_t(s);
            group = group << 6 | std::uint32_t(s & 63);
        }
        *to++ = static_cast<unsigned char>(group >> 16);
        if (digits - i == 3) {
            *to++ = static_cast<unsigned char>(group >> 8);
        }
    }
    return (invalid & 0x80000000u) == 0;
}

TakenBuffers takeBuffers(std::vector<unsigned char>& document, bool binary, FsPolicy& policy,
                         const std::string& file) {
    std::optional<GlbLayout> glb;
    if (binary && !(glb = glbLayout(document))) {
        return {};
    }
    const std::size_t jsonStart = glb ? glb->jsonStart : 0;
    const std::size_t jsonLength = glb ? glb->jsonLength : document.size();
    const std::string_view json(reinterpret_cast<const char*>(document.data()) + jsonStart,
                                jsonLength);
    const std::optional<std::vector<BufferMembers>> buffers = scanBufferMembers(json);
    if (!buffers || buffers->empty()) {
        return {};
    }
    const std::optional<std::vector<Take>> takes =
        planTakes(json, *buffers, binary, glb && glb->binLength > 0);
    if (!takes) {
        return {};
    }
    TakenBuffers taken;
    const bool fromBin = takes->front().source == Source::BinChunk;
    if (fromBin && takes->front().byteLength > glb->binLength) {
        fail(file, "buffer 0: byteLength " + std::to_string(takes->front().byteLength) +
                       " is past the end of the BIN chunk (" + std::to_string(glb->binLength) +
                       " bytes)");
    }
    for (const Take& take : *takes) {
        taken.buffers.emplace_back(take.buffer, take.source == Source::BinChunk
                                                    ? std::vector<unsigned char>()
                                                    : readTake(take, json, policy, file));
    }
    std::string standIn = standInJson(json, *takes);
    if (!glb) {
        std::vector<unsigned char>(standIn.begin(), standIn.end()).swap(document);
        return taken;
    }
    std::vector<unsigned char> container = standInGlb(document, std::move(standIn), fromBin);
    if (fromBin) { // the chunk moves to the front of the file's own array, which becomes buffer 0
        document.erase(document.begin(), document.begin() + long(glb->binStart));
        document.resize(takes->front().byteLength);
        taken.buffers.front().second = std::move(document);
    }
    document = std::move(container);
    return taken;
}

void returnBuffers(tinygltf::Model& model, TakenBuffers& taken, const std::string& file) {
    for (auto& [index, bytes] : taken.buffers) {
        if (std::size_t(index) >= model.buffers.size() || model.buffers[index].data.size() != 4) {
            fail(file, "buffer " + std::to_string(index) + " was not parsed as it was read");
        }
        model.buffers[index].data = std::move(bytes); // empty for a buffer without data
        model.buffers[index].uri.clear();             // the stand-in's
    }
    taken.buffers.clear();
}

} // namespace wf::gltf
