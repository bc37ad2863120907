// The hand-made corpus in tests/gltf_corpus (written by make_corpus.py): every valid file loads
// with the triangles, lights, cameras, images and attribute arrays expected.tsv lists, and
// every invalid one is refused with one line "<file>: <problem>" naming the problem.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <sstream>

#include "errors.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {
namespace {

struct Expectation {
    std::string file;
    bool loads = false;
    size_t triangles = 0;
    std::map<std::string, size_t> counts; // key=value pairs after the triangle count
    std::string substring;                // for refusals
};

std::vector<Expectation> readExpectations() {
    std::ifstream in(std::string(WF_TEST_CORPUS_DIR) + "/expected.tsv");
    std::vector<Expectation> out;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') {
            continue;
        }
        Expectation e;
        const size_t tab = line.find('\t');
        e.file = line.substr(0, tab);
        std::istringstream rest(line.substr(tab + 1));
        std::string verb;
        rest >> verb;
        e.loads = verb == "loads";
        if (e.loads) {
            rest >> e.triangles;
            std::string pair;
            while (rest >> pair) {
                const size_t eq = pair.find('=');
                e.counts[pair.substr(0, eq)] = std::stoul(pair.substr(eq + 1));
            }
        } else {
            std::getline(rest, e.substring);
            e.substring.erase(0, e.substring.find_first_not_of(' '));
        }
        out.push_back(e);
    }
    return out;
}

size_t count(const Scene& scene, const std::string& key) {
    const SurfaceData& s = scene.surface;
    if (key == "lights") return scene.lights.size();
    if (key == "cameras") return scene.cameras.size();
    if (key == "images") return s.images.size();
    if (key == "normals") return s.normals.empty() ? 0 : 1;
    if (key == "tangents") return s.tangents.empty() ? 0 : 1;
    if (key == "uv0") return s.uv0.empty() ? 0 : 1;
    if (key == "uv1") return s.uv1.empty() ? 0 : 1;
    if (key == "env") return scene.environment.present() ? 1 : 0;
    ADD_FAILURE() << "unknown key " << key;
    return 0;
}

TEST(GltfCorpus, EveryFileLoadsOrIsRefusedAsExpected) {
    const std::vector<Expectation> expectations = readExpectations();
    ASSERT_GE(expectations.size(), 60u);
    size_t valid = 0, invalid = 0;
    for (const Expectation& e : expectations) {
        const std::string path = std::string(WF_TEST_CORPUS_DIR) + "/" + e.file;
        SCOPED_TRACE(e.file);
        try {
            Scene scene = loadGltf(path);
            EXPECT_TRUE(e.loads) << "loaded, but should be refused (" << e.substring << ")";
            EXPECT_EQ(scene.triangles.size(), e.triangles);
            for (const auto& [key, value] : e.counts) {
                EXPECT_EQ(count(scene, key), value) << key;
            }
            // Parallel arrays stay parallel, and every texture reference has an image.
            for (size_t n : {scene.surface.normals.size(), scene.surface.uv0.size(),
                             scene.surface.uv1.size(), scene.surface.tangents.size()}) {
                EXPECT_TRUE(n == 0 || n == scene.triangles.size());
            }
            for (uint32_t image : scene.surface.refImage) {
                EXPECT_TRUE(image < scene.surface.images.size() || image == UINT32_MAX);
            }
            valid += e.loads;
        } catch (const InputError& error) {
            const std::string message = error.what();
            EXPECT_FALSE(e.loads) << "refused: " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
            EXPECT_NE(message.find(e.substring), std::string::npos)
                << message << "\n  should mention: " << e.substring;
            invalid += !e.loads;
        }
    }
    EXPECT_GE(valid, 30u);
    EXPECT_GE(invalid, 30u);
}

// Every refusal and warning over the corpus in the project's words: none passes another
// library's message through (tinygltf's, its JSON parser's).
TEST(GltfCorpus, NoMessageSpeaksAnotherLibrarysWords) {
    const char* foreign[] = {"tinygltf", "json.exception", "File not found :", "[json",
                             "Failed to load external", "property is missing", "` field"};
    size_t messages = 0;
    for (const Expectation& e : readExpectations()) {
        const std::string path = std::string(WF_TEST_CORPUS_DIR) + "/" + e.file;
        std::vector<std::string> lines;
        try {
            loadGltf(path, &lines);
        } catch (const InputError& error) {
            lines.push_back(error.what());
        }
        for (const std::string& line : lines) {
            ++messages;
            // What follows the file's name (one corpus file is named after tinygltf).
            const size_t at = line.find(path);
            const std::string said = at == std::string::npos ? line : line.substr(at + path.size());
            for (const char* words : foreign)
                EXPECT_EQ(said.find(words), std::string::npos) << e.file << ": " << line;
        }
    }
    EXPECT_GE(messages, 80u);
}

} // namespace
} // namespace wf
