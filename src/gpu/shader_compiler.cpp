#include "gpu/shader_compiler.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include "errors.h"
#include "image/atomic_file.h"

namespace fs = std::filesystem;

namespace wf {
namespace {

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InternalError("cannot read shader source " + path.string());
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

uint64_t fnv1a(const std::string& text, uint64_t hash = 1469598103934665603ull) {
    for (unsigned char c : text) {
        hash ^= c;
        hash *= 1099511628211ull;
    }
    return hash;
}

// Resolves `#include "x.h"` against the including file's folder, then the shader folder (so
// "bsdf/bsdf.h" from anywhere), and never outside it. (DirStackFileIncluder.h is not shipped by Debian.)
class ShaderIncluder : public glslang::TShader::Includer {
public:
    explicit ShaderIncluder(fs::path root) : root_(std::move(root)) {}

    IncludeResult* includeLocal(const char* header, const char* includer, size_t) override {
        fs::path from = fs::path(includer).parent_path();
        for (const fs::path& dir : {from, root_}) {
            fs::path candidate = fs::weakly_canonical(dir / header);
            if (!isInsideRoot(candidate) || !fs::is_regular_file(candidate))
                continue;
            auto* text = new std::string(readText(candidate));
            return new IncludeResult(candidate.string(), text->data(), text->size(), text);
        }
        return nullptr;
    }
    IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override {
        return includeLocal(header, includer, depth);
    }
    void releaseInclude(IncludeResult* result) override {
        if (result) {
            delete static_cast<std::string*>(result->userData);
            delete result;
        }
    }

private:
    bool isInsideRoot(const fs::path& path) const {
        auto rel = path.lexically_relative(root_);
        return !rel.empty() && *rel.begin() != "..";
    }
    fs::path root_;
};

void ensureGlslangInitialized() {
    static std::once_flag once;
    std::call_once(once, [] {
        glslang::InitializeProcess();
        std::atexit([] { glslang::FinalizeProcess(); });
    });
}

std::vector<uint32_t> readSpirv(const fs::path& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in)
        return {};
    auto bytes = static_cast<size_t>(in.tellg());
    if (bytes == 0 || bytes % 4 != 0)
        return {};
    std::vector<uint32_t> words(bytes / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(words.data()), static_cast<std::streamsize>(bytes));
    if (!in || words[0] != 0x07230203u) // SPIR-V magic: anything else is a torn or foreign file
        return {};
    return words;
}

} // namespace

std::string defaultShaderDir() {
    if (const char* env = std::getenv("WAVEFRONT_SHADER_DIR"); env && *env)
        return env;
    std::error_code error;
    fs::path exe = fs::read_symlink("/proc/self/exe", error);
    if (!error && fs::is_regular_file(exe.parent_path() / "shaders" / "raygen.comp"))
        return (exe.parent_path() / "shaders").string();
    return WF_SOURCE_SHADER_DIR;
}

std::string defaultShaderCacheDir() {
    if (const char* env = std::getenv("WAVEFRONT_CACHE_DIR"))
        return env; // may be empty: no cache
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return (fs::path(xdg) / "wavefront").string();
    if (const char* home = std::getenv("HOME"); home && *home)
        return (fs::path(home) / ".cache" / "wavefront").string();
    return {};
}

struct ShaderCompiler::MemoryCache {
    std::mutex mutex;
    std::map<std::string, std::vector<uint32_t>> spirv; // by file and cache key
};

ShaderCompiler::ShaderCompiler() : ShaderCompiler(defaultShaderDir(), defaultShaderCacheDir()) {}

ShaderCompiler::ShaderCompiler(std::string shaderDir, std::string cacheDir)
    : shaderDir_(fs::weakly_canonical(shaderDir).string()), cacheDir_(std::move(cacheDir)),
      memory_(std::make_shared<MemoryCache>()) {
    if (!fs::is_regular_file(fs::path(shaderDir_) / "raygen.comp"))
        throw InternalError("shader folder " + shaderDir_ +
                            " has no raygen.comp; set WAVEFRONT_SHADER_DIR");
    // Every file under the folder, by its path there, so that a cached SPIR-V is never reused
    // after any included source changed, wherever it lives.
    std::vector<fs::path> sources;
    for (const auto& entry : fs::recursive_directory_iterator(shaderDir_))
        if (entry.is_regular_file())
            sources.push_back(entry.path());
    std::sort(sources.begin(), sources.end());
    sourcesHash_ = fnv1a("wavefront-spirv-cache-v2");
    for (const auto& path : sources)
        sourcesHash_ = fnv1a(path.lexically_relative(shaderDir_).generic_string() +
                                       readText(path),
                                   sourcesHash_);
}

std::string ShaderCompiler::cacheKey(const std::string& source,
                                     const ShaderDefines& defines) const {
    uint64_t hash = fnv1a(source, sourcesHash_);
    for (const auto& [name, value] : defines)
        hash = fnv1a(name + "=" + value + ";", hash);
    hash = fnv1a(std::to_string(glslang::GetVersion().major) + "." +
                     std::to_string(glslang::GetVersion().minor),
                 hash);
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

CompiledShader ShaderCompiler::compile(const std::string& file,
                                       const ShaderDefines& defines) const {
    fs::path path = fs::path(shaderDir_) / file;
    std::string source = readText(path);
    const std::string key = file + "-" + cacheKey(source, defines);
    if (!memory_)
        throw InternalError("shader compiler used before construction");
    {
        std::lock_guard<std::mutex> lock(memory_->mutex);
        if (auto found = memory_->spirv.find(key); found != memory_->spirv.end())
            return {found->second, true};
    }
    auto remember = [&](const std::vector<uint32_t>& words) {
        std::lock_guard<std::mutex> lock(memory_->mutex);
        memory_->spirv.emplace(key, words);
    };
    fs::path cached;
    if (!cacheDir_.empty()) {
        cached = fs::path(cacheDir_) / (path.stem().string() + "-" + cacheKey(source, defines) +
                                        ".spv");
        if (auto words = readSpirv(cached); !words.empty()) {
            remember(words);
            return {std::move(words), true};
        }
    }

    ensureGlslangInitialized();
    std::string preamble;
    for (const auto& [name, value] : defines)
        preamble += "#define " + name + " " + value + "\n";
    glslang::TShader shader(EShLangCompute);
    const char* text = source.c_str();
    const char* name = path.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &name, 1);
    shader.setPreamble(preamble.c_str());
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_2);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_5);
    ShaderIncluder includer(shaderDir_);
    const auto messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 460, false, messages, includer))
        throw InternalError("glslang failed to compile " + path.string() + ":\n" +
                            shader.getInfoLog());
    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages))
        throw InternalError("glslang failed to link " + path.string() + ":\n" +
                            program.getInfoLog());
    CompiledShader result;
    glslang::SpvOptions options;
    options.disableOptimizer = false;
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), result.spirv, &options);
    remember(result.spirv);

    if (!cached.empty()) {
        // A cache that cannot be written costs time, not correctness: warn and go on.
        try {
            fs::create_directories(cached.parent_path());
            writeFileAtomically(cached.string(), [&](const std::string& tmp) {
                std::ofstream out(tmp, std::ios::binary);
                out.write(reinterpret_cast<const char*>(result.spirv.data()),
                          static_cast<std::streamsize>(result.spirv.size() * 4));
                if (!out)
                    throw InternalError("write failed");
            });
        } catch (const std::exception& error) {
            std::fprintf(stderr, "wavefront: warning: SPIR-V cache not written (%s)\n",
                         error.what());
        }
    }
    return result;
}

} // namespace wf
