// EXT_meshopt_compression / KHR_meshopt_compression bufferViews through meshoptimizer 0.18.
// Its decoders check the bitstream but assert() their size preconditions (off in Debian's
// build), so every precondition is checked here first, as the specification words them.
#include <meshoptimizer.h>

#include <algorithm>

#include "scene/gltf/gltf_accessors.h"
#include "scene/gltf/compression/gltf_codecs.h"

namespace wf::gltf {
namespace {

const char* modeName(MeshoptView::Mode mode) {
    switch (mode) {
    case MeshoptView::ATTRIBUTES: return "ATTRIBUTES";
    case MeshoptView::TRIANGLES: return "TRIANGLES";
    default: return "INDICES";
    }
}

const char* filterName(MeshoptView::Filter filter) {
    switch (filter) {
    case MeshoptView::NONE: return "NONE";
    case MeshoptView::OCTAHEDRAL: return "OCTAHEDRAL";
    case MeshoptView::QUATERNION: return "QUATERNION";
    default: return "EXPONENTIAL";
    }
}

// The first byte of each stream: 0xa0 + version for attributes, 0xe0 + version for triangles,
// 0xd0 + version for indices. meshoptimizer 0.18 decodes vertex version 0 only; KHR allows 1.
constexpr unsigned char VERTEX_V1_HEADER = 0xa1;

// A lower bound on the compressed size of a valid stream, so that a few bytes claiming
// gigabytes are refused before the output is allocated. Attributes: every block stores, per
// byte of the element, one 2-bit header per group of 16 elements, and the tail holds one whole
// element; triangles take a code byte each and indices at least a byte each.
std::size_t minimumBytes(const MeshoptView& m) {
    if (m.mode == MeshoptView::TRIANGLES) {
        return m.count / 3;
    }
    if (m.mode == MeshoptView::INDICES) {
        return m.count;
    }
    const std::size_t blockElements = std::min<std::size_t>((8192 / m.byteStride) & ~15u, 256);
    const std::size_t fullBlocks = m.count / blockElements, rest = m.count % blockElements;
    const auto headerBytes = [](std::size_t elements) { return ((elements + 15) / 16 + 3) / 4; };
    return m.byteStride * (fullBlocks * headerBytes(blockElements) + headerBytes(rest) + 1);
}

} // namespace

void checkMeshoptParameters(const MeshoptView& m, const std::string& file) {
    const std::string where = "bufferView " + std::to_string(m.view) + " " + m.extension;
    const std::string stride = "byteStride " + std::to_string(m.byteStride);
    const std::string mode = std::string("mode ") + modeName(m.mode);
    const std::string filter = std::string("filter ") + filterName(m.filter);
    if (m.mode == MeshoptView::ATTRIBUTES) {
        if (m.byteStride == 0 || m.byteStride % 4 != 0 || m.byteStride > 256) {
            fail(file, where + ": " + stride + " is invalid for " + mode +
                           " (a multiple of 4 up to 256)");
        }
    } else {
        if (m.byteStride != 2 && m.byteStride != 4) {
            fail(file, where + ": " + stride + " is invalid for " + mode + " (2 or 4)");
        }
        if (m.filter != MeshoptView::NONE) {
            fail(file, where + ": " + filter + " applies to ATTRIBUTES only, not to " + mode);
        }
        if (m.mode == MeshoptView::TRIANGLES && m.count % 3 != 0) {
            fail(file, where + ": count " + std::to_string(m.count) +
                           " is not a whole number of triangles");
        }
    }
    const bool strideFits =
        m.filter == MeshoptView::NONE ||
        (m.filter == MeshoptView::OCTAHEDRAL && (m.byteStride == 4 || m.byteStride == 8)) ||
        (m.filter == MeshoptView::QUATERNION && m.byteStride == 8) ||
        (m.filter == MeshoptView::EXPONENTIAL && m.byteStride % 4 == 0);
    if (!strideFits) {
        fail(file, where + ": " + filter + " does not apply to elements of " + stride +
                       " (OCTAHEDRAL: 4 or 8, QUATERNION: 8, EXPONENTIAL: a multiple of 4)");
    }
    if (m.count > MAX_ACCESSOR_ELEMENTS * 4) { // a view may hold several accessors' elements
        fail(file, where + ": count " + std::to_string(m.count) + " is over the limit of " +
                       std::to_string(MAX_ACCESSOR_ELEMENTS * 4));
    }
    if (m.count > 0 && m.byteLength < minimumBytes(m)) {
        fail(file, where + ": " + std::to_string(m.byteLength) + " bytes cannot hold " +
                       std::to_string(m.count) + " elements of " + std::to_string(m.byteStride) +
                       " bytes (" + modeName(m.mode) + " data needs at least " +
                       std::to_string(minimumBytes(m)) + ")");
    }
}

std::vector<unsigned char> decodeMeshopt(const MeshoptView& m, const unsigned char* source,
                                         const std::string& file) {
    const std::string where = "bufferView " + std::to_string(m.view) + " " + m.extension;
    std::vector<unsigned char> out(m.count * m.byteStride);
    if (m.count == 0) {
        return out;
    }
    int result = 0;
    switch (m.mode) {
    case MeshoptView::ATTRIBUTES:
        if (m.byteLength > 0 && source[0] == VERTEX_V1_HEADER) {
            fail(file, where + " uses version 1 of meshopt's vertex codec, which Debian 12's "
                               "meshoptimizer 0.18 cannot decode");
        }
        result = meshopt_decodeVertexBuffer(out.data(), m.count, m.byteStride, source,
                                            m.byteLength);
        break;
    case MeshoptView::TRIANGLES:
        result = meshopt_decodeIndexBuffer(out.data(), m.count, m.byteStride, source,
                                           m.byteLength);
        break;
    case MeshoptView::INDICES:
        result = meshopt_decodeIndexSequence(out.data(), m.count, m.byteStride, source,
                                             m.byteLength);
        break;
    }
    if (result != 0) {
        fail(file, where + ": " + std::to_string(m.byteLength) + " bytes are not valid " +
                       modeName(m.mode) + " data for " + std::to_string(m.count) +
                       " elements of " + std::to_string(m.byteStride) + " bytes (meshopt " +
                       "error " + std::to_string(result) + ")");
    }
    // In place; checkMeshoptParameters has matched each filter's strides.
    if (m.filter == MeshoptView::OCTAHEDRAL) {
        meshopt_decodeFilterOct(out.data(), m.count, m.byteStride);
    } else if (m.filter == MeshoptView::QUATERNION) {
        meshopt_decodeFilterQuat(out.data(), m.count, m.byteStride);
    } else if (m.filter == MeshoptView::EXPONENTIAL) {
        meshopt_decodeFilterExp(out.data(), m.count, m.byteStride);
    }
    return out;
}

} // namespace wf::gltf
