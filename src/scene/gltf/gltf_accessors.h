// Reads vertex attributes and indices out of a parsed glTF model. tinygltf 2.7.0 checks few of
// the indices, offsets, strides and counts it parses, so every one is checked here against the
// model's arrays and buffer sizes before a byte is read, and element counts are bounded before
// anything is allocated. Dense, sparse and bufferView-less (all zero) accessors are read;
// integer components are converted as glTF says (normalized or not, KHR_mesh_quantization).
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace tinygltf {
class Model;
struct Primitive;
}

namespace wf::gltf {

// One accessor may hold at most this many elements: far above real meshes (300k-triangle
// scenes have ~1M vertices), and it keeps a tiny file with a huge `count` from allocating
// gigabytes.
constexpr std::size_t MAX_ACCESSOR_ELEMENTS = std::size_t(1) << 24;

// Every problem in a scene file becomes one InputError("<file>: <problem>"); the loader and the
// accessor reader share these so their messages read alike.
[[noreturn]] void fail(const std::string& file, const std::string& problem);
// Fails unless 0 <= index < size; `by` names what holds the index, `what` what it points at.
void checkIndex(const std::string& file, int index, std::size_t size, const std::string& what,
                const std::string& by);
// One warning line "warning: <file>: <problem>" (kind "note" for notes), collected while a
// WarningSink is alive on this thread, else printed to stderr at once.
void warn(const std::string& file, const std::string& problem, const char* kind = "warning");

// The first of the primitive's accessors (indices, attributes, morph targets) whose bufferView
// lies in a buffer without data (gltf_buffer_streaming keeps a buffer without uri empty), or -1.
int accessorWithoutData(const tinygltf::Model& model, const tinygltf::Primitive& primitive);

// Collects the warnings of one load, so a refused file prints its one error line and nothing
// else, and a loaded one prints its warnings after everything else about it was checked.
class WarningSink {
public:
    WarningSink();
    ~WarningSink();
    WarningSink(const WarningSink&) = delete;
    WarningSink& operator=(const WarningSink&) = delete;
    std::vector<std::string> take() { return std::move(lines_); }

private:
    std::vector<std::string> lines_;
    std::vector<std::string>* previous_;
};

// Which component types an attribute accepts (bit i set: componentType 5120 + i).
enum ComponentMask : unsigned {
    BYTE_BIT = 1u << 0,
    UBYTE_BIT = 1u << 1,
    SHORT_BIT = 1u << 2,
    USHORT_BIT = 1u << 3,
    UINT_BIT = 1u << 5,
    FLOAT_BIT = 1u << 6,
    // Core glTF plus KHR_mesh_quantization: floats and 8/16-bit integers.
    ATTRIBUTE_TYPES = BYTE_BIT | UBYTE_BIT | SHORT_BIT | USHORT_BIT | FLOAT_BIT,
    INDEX_TYPES = UBYTE_BIT | USHORT_BIT | UINT_BIT,
};

// Accessors converted to float, `components` values per element, all finite.
struct FloatArray {
    std::vector<float> values;
    std::size_t count = 0;
    int components = 0;
    const float* operator[](std::size_t i) const { return values.data() + i * components; }
};

// Holds the model and file name by reference: both must outlive the reader.
class AccessorReader {
public:
    AccessorReader(const tinygltf::Model& model, const std::string& file)
        : model_(model), file_(file) {}

    // An attribute of `components` (1 to 4, or 16 for MAT4) values per element. Meshes instanced by many
    // nodes share accessors, so each is read once; the reference stays valid for the reader's
    // lifetime. Non-finite values fail, naming the accessor and element.
    const FloatArray& floats(int accessor, const std::string& role, int components);
    // u8/u16/u32 indices widened to u32, each below vertexCount.
    std::vector<std::uint32_t> indices(int accessor, std::size_t vertexCount,
                                       const std::string& where);
    const tinygltf::Model& model() const { return model_; }
    // Total elements read so far, for the loader's overall budget.
    std::size_t elementsRead() const { return elementsRead_; }

private:
    struct Dense;
    Dense dense(int index, const std::string& name, unsigned allowedTypes, int components);
    template <class T, class Read>
    std::vector<T> read(int index, const std::string& name, unsigned allowedTypes,
                        int components, Read readComponent);

    const tinygltf::Model& model_;
    const std::string& file_;
    std::unordered_map<long long, FloatArray> floatCache_;
    std::size_t elementsRead_ = 0;
};

} // namespace wf::gltf
