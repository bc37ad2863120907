// tinygltf's default hooks read any path a file names, "../" and absolute ones included, and
// hand every image to stb_image; these replacements confine it to the scene's folder.
#include "scene/gltf/io/gltf_file_access.h"

#include <tiny_gltf.h>

#include <cstring>

#include <algorithm>
#include <fstream>
#include <optional>

#include "scene/gltf/io/gltf_buffer_streaming.h"

namespace wf::gltf {
namespace {

namespace fs = std::filesystem;

// A URI as the file wrote it, taken relative to the scene's folder.
std::optional<fs::path> resolveUri(FsPolicy& policy, const std::string& uri) {
    auto refuse = [&](const std::string& why) -> std::optional<fs::path> {
        if (policy.refusal.empty()) { // a URI may be megabytes of data: quote its start
            const std::string shown = uri.size() > 60 ? uri.substr(0, 60) + "..." : uri;
            policy.refusal = "refused to read '" + shown + "': " + why;
        }
        return std::nullopt;
    };
    // tinygltf decodes the data: URIs it can and hands the rest over as file names.
    if (uri.rfind("data:", 0) == 0) {
        return refuse("a data: uri must be 'data:<media type>;base64,<data>' (a buffer's may "
                      "also hold percent-encoded data) with a media type glTF allows");
    }
    const fs::path relative(uri);
    if (uri.empty() || relative.is_absolute() || relative.has_root_path()) {
        return refuse("only paths relative to the scene's folder are allowed");
    }
    for (const fs::path& part : relative) {
        if (part == "..") {
            return refuse("'..' is not allowed in paths");
        }
    }
    std::error_code ec;
    const fs::path resolved = fs::weakly_canonical(policy.folder / relative, ec);
    if (ec) {
        return refuse(ec.message());
    }
    // A symbolic link may still lead out of the folder: compare the canonical paths.
    auto [folderEnd, unused] = std::mismatch(policy.folder.begin(), policy.folder.end(),
                                             resolved.begin(), resolved.end());
    if (folderEnd != policy.folder.end()) {
        return refuse("it resolves outside the scene's folder");
    }
    return resolved;
}

// tinygltf asks for "<base dir>/<uri>" and then "./<uri>"; both are taken relative to the
// scene's folder, never to the working directory.
std::optional<fs::path> resolveInFolder(FsPolicy& policy, const std::string& requested) {
    std::string uri = requested;
    std::string prefix = policy.folder.string();
    if (prefix.empty() || prefix.back() != '/') {
        prefix += '/';
    }
    if (uri.rfind(prefix, 0) == 0) {
        uri.erase(0, prefix.size());
    } else if (uri.rfind("./", 0) == 0) {
        uri.erase(0, 2);
    }
    return resolveUri(policy, uri);
}

// tinygltf 2.7 decodes data: URIs only for the media types it knows, and takes any other
// (EXT_texture_webp's image/webp) for a file name; such images are decoded here.
constexpr const char* WEBP_DATA_URI = "data:image/webp;base64,";

std::optional<std::string> webpDataUri(const FsPolicy& policy, const std::string& requested) {
    std::string prefix = policy.folder.string();
    if (prefix.empty() || prefix.back() != '/') {
        prefix += '/';
    }
    for (const std::string& base : {prefix, std::string("./"), std::string()}) {
        if (requested.rfind(base + WEBP_DATA_URI, 0) == 0) {
            return requested.substr(base.size() + std::strlen(WEBP_DATA_URI));
        }
    }
    return std::nullopt;
}

bool fileExists(const std::string& path, void* userData) {
    if (webpDataUri(*static_cast<FsPolicy*>(userData), path)) {
        return true;
    }
    std::optional<fs::path> resolved = resolveInFolder(*static_cast<FsPolicy*>(userData), path);
    std::error_code ec;
    return resolved && fs::is_regular_file(*resolved, ec);
}

std::string expandFilePath(const std::string& path, void*) {
    return path; // no "~" or environment expansion: URIs are plain relative paths
}

// Reads a file resolveUri or resolveInFolder accepted, under the size limits.
bool readResolved(FsPolicy& policy, const std::optional<fs::path>& resolved,
                  std::vector<unsigned char>& out, std::string& error) {
    if (!resolved) {
        error = policy.refusal;
        return false;
    }
    if (!readLimited(*resolved, out, error)) {
        return false;
    }
    policy.bytesRead += out.size();
    if (policy.bytesRead > MAX_TOTAL_BYTES) {
        out.clear();
        error = "the scene's files together exceed 2 GiB";
        return false;
    }
    return true;
}

bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* userData) {
    FsPolicy& policy = *static_cast<FsPolicy*>(userData);
    if (std::optional<std::string> base64 = webpDataUri(policy, path)) {
        // tinygltf URI-decodes the name first, which turns base64's '+' into ' '.
        std::replace(base64->begin(), base64->end(), ' ', '+');
        if (decodeBase64(base64->data(), base64->size(), *out)) {
            return true;
        }
        *err += "a WebP data URI is not valid base64";
        return false;
    }
    std::string why;
    if (readResolved(policy, resolveInFolder(policy, path), *out, why)) {
        return true;
    }
    *err += why;
    return false;
}

bool refuseWrite(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err += "writing is disabled";
    return false;
}

// Keeps the bytes of URI images for gltf_images, which checks and decodes them. For an image
// in a bufferView, tinygltf passes a pointer it never range-checked: it is not touched here,
// and gltf_images reads the bufferView itself after checking it.
bool keepImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
               const unsigned char* bytes, int size, void* userData) {
    if (image->bufferView != -1 || size <= 0) {
        return true;
    }
    auto& images = static_cast<FsPolicy*>(userData)->images;
    images[index].assign(bytes, bytes + size);
    return true;
}

} // namespace

bool readLimited(const fs::path& path, std::vector<unsigned char>& out, std::string& error) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) {
        error = "not found or not a regular file";
        return false;
    }
    const uintmax_t size = fs::file_size(path, ec);
    if (ec || size > MAX_FILE_BYTES) {
        error = ec ? ec.message() : "larger than 1 GiB";
        return false;
    }
    std::ifstream in(path, std::ios::binary);
    out.resize(static_cast<size_t>(size));
    if (!in || !in.read(reinterpret_cast<char*>(out.data()), std::streamsize(size))) {
        error = "read failed";
        return false;
    }
    return true;
}

bool readInFolder(FsPolicy& policy, const std::string& uri, std::vector<unsigned char>& out,
                  std::string& error) {
    return readResolved(policy, resolveUri(policy, uri), out, error);
}

void restrictFileAccess(tinygltf::TinyGLTF& gltf, FsPolicy& policy) {
    gltf.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &policy});
    gltf.SetImageLoader(&keepImage, &policy);
}

bool nestedTooDeep(const unsigned char* text, size_t length) {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < length; ++i) {
        const unsigned char c = text[i];
        if (inString) {
            i += c == '\\' ? 1 : 0; // skip the escaped character
            inString = c != '"';
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > MAX_JSON_DEPTH) {
                return true;
            }
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

} // namespace wf::gltf
