// GLSL -> SPIR-V at run time with the glslang library. Each scene gets its own variant through
// `#define`s; the SPIR-V is cached on disk, keyed by a hash of the sources, the defines and the
// compiler version, so a second run of the same scene compiles nothing.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace wf {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

struct CompiledShader {
    std::vector<uint32_t> spirv;
    bool fromCache = false;
};

class ShaderCompiler {
public:
    // shaderDir: WAVEFRONT_SHADER_DIR, else <executable dir>/shaders, else the source tree.
    // cacheDir: WAVEFRONT_CACHE_DIR, else $XDG_CACHE_HOME/wavefront, else ~/.cache/wavefront;
    // an empty string disables the cache.
    ShaderCompiler();
    ShaderCompiler(std::string shaderDir, std::string cacheDir);

    // `file` is relative to the shader folder, e.g. "shade.comp". Throws InternalError with
    // glslang's log, verbatim, on failure.
    CompiledShader compile(const std::string& file, const ShaderDefines& defines) const;

    const std::string& shaderDir() const { return shaderDir_; }
    const std::string& cacheDir() const { return cacheDir_; }

private:
    std::string cacheKey(const std::string& source, const ShaderDefines& defines) const;

    std::string shaderDir_;
    std::string cacheDir_;
    uint64_t sourcesHash_ = 0; // every file under the shader folder, read once
    // SPIR-V compiled or read by this compiler (and its copies), so the renderers of a frame
    // sequence read neither glslang nor the disk again.
    struct MemoryCache;
    std::shared_ptr<MemoryCache> memory_;
};

std::string defaultShaderDir();
std::string defaultShaderCacheDir();

} // namespace wf
