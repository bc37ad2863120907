// Buffers read around tinygltf (gltf_buffer_streaming.h): the base64 decoder, the JSON scan
// that finds the buffers' members, and loads that must give the same scene whichever way the
// bytes arrive, or one clear error.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "errors.h"
#include "scene/gltf/io/gltf_buffer_streaming.h"
#include "scene/gltf/io/gltf_json_scan.h"
#include "scene/gltf/gltf_loader.h"
#include "mini_gltf.h"

namespace wf {
namespace {

using test::MiniGltf;
using test::TempDir;

TEST(Base64, DecodesWhatWasEncodedWithAndWithoutPadding) {
    std::mt19937 rng(7);
    for (size_t length = 0; length < 80; ++length) {
        std::vector<uint8_t> bytes(length);
        for (uint8_t& b : bytes)
            b = uint8_t(rng());
        const std::string padded = test::base64(bytes);
        std::string unpadded = padded;
        while (!unpadded.empty() && unpadded.back() == '=')
            unpadded.pop_back();
        for (const std::string& text : {padded, unpadded}) {
            std::vector<unsigned char> decoded;
            ASSERT_TRUE(gltf::decodeBase64(text.data(), text.size(), decoded)) << text;
            EXPECT_EQ(std::vector<uint8_t>(decoded.begin(), decoded.end()), bytes) << text;
        }
    }
}

TEST(Base64, RefusesWhatIsNotBase64) {
    const std::vector<std::string> texts = {"Q",    "QUJDR", "QQ=A",   "QQ=",
                                            "Q===", "QU\nJD", "QUJ-", std::string("QUJD\0AAA", 8)};
    for (const std::string& text : texts) {
        std::vector<unsigned char> decoded;
        EXPECT_FALSE(gltf::decodeBase64(text.data(), text.size(), decoded)) << text;
    }
}

std::string spanText(std::string_view json, gltf::JsonSpan span) {
    return std::string(json.substr(span.begin, span.end - span.begin));
}

TEST(JsonScan, FindsEachBuffersMembersPastDistractions) {
    const std::string json =
        R"({"asset":{"version":"2.0","x":"}]\"{["},"uri":"not a buffer",)"
        R"("images":[{"uri":"a.png"}],"buffers":[{"name":"{","byteLength":12,"uri":"a.bin"},)"
        R"({"uri":"b\/c.bin","byteLength":8}, {"byteLength":4}],"z":[1,[2,{"buffers":3}]]})";
    const auto buffers = gltf::scanBufferMembers(json);
    ASSERT_TRUE(buffers);
    ASSERT_EQ(buffers->size(), 3u);
    EXPECT_EQ(spanText(json, (*buffers)[0].uri), "\"a.bin\"");
    EXPECT_EQ(spanText(json, (*buffers)[0].byteLength), "12");
    EXPECT_FALSE((*buffers)[0].uriEscaped);
    EXPECT_TRUE((*buffers)[1].uriEscaped);
    EXPECT_EQ(spanText(json, (*buffers)[1].byteLength), "8");
    EXPECT_FALSE((*buffers)[2].uri.present());
}

TEST(JsonScan, GivesNoAnswerWhereTinygltfMightReadOtherwise) {
    for (const char* json : {
             R"({"buffers":[],"buffers":[{"uri":"a.bin","byteLength":4}]})", // last one wins
             R"({"buff\u0065rs":[{"uri":"a.bin","byteLength":4}]})",
             R"({"buffers":[{"uri":"a.bin","uri":"b.bin","byteLength":4}]})",
             R"({"buffers":[{"\u0075ri":"a.bin","byteLength":4}]})",
             R"({"buffers":[{"uri":"a.bin","byteLength":4}]} trailing)",
             R"({"buffers":[{"uri":"a.bin","byteLength":4})",
             R"([{"buffers":[]}])",
         }) {
        EXPECT_FALSE(gltf::scanBufferMembers(json)) << json;
    }
    const auto none = gltf::scanBufferMembers("\xEF\xBB\xBF {\"asset\":{}} ");
    ASSERT_TRUE(none);
    EXPECT_TRUE(none->empty());
}

// Two triangles with normals, indexed, so every accessor kind the streamed bytes feed is read.
MiniGltf twoTriangles() {
    MiniGltf g;
    const std::vector<float> xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0.5f};
    const std::vector<float> normals = {0, 0, 1, 0, 0.6f, 0.8f, 0.6f, 0, 0.8f, 0, 0, 1};
    const int positions = g.addPositions(xyz);
    const int normalView = g.addView(normals.data(), normals.size() * 4);
    const int normal = g.addAccessor(normalView, test::F32, 4, "VEC3");
    const int indices = g.addIndices(std::vector<uint16_t>{0, 1, 2, 2, 1, 3}, test::U16);
    g.addMesh(positions, indices, -1, 4, ",\"NORMAL\":" + std::to_string(normal));
    g.nodes.push_back("{\"mesh\":0}");
    return g;
}

void expectSameGeometry(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    ASSERT_EQ(a.surface.normals.size(), b.surface.normals.size());
    EXPECT_EQ(std::memcmp(a.triangles.data(), b.triangles.data(),
                          a.triangles.size() * sizeof(Triangle)),
              0);
    EXPECT_EQ(std::memcmp(a.surface.normals.data(), b.surface.normals.data(),
                          a.surface.normals.size() * sizeof(a.surface.normals[0])),
              0);
}

TEST(BufferStreaming, EveryWayTheBytesArriveGivesTheSameScene) {
    TempDir dir;
    MiniGltf g = twoTriangles();
    const Scene embedded = loadGltf(g.write(dir, "embedded.gltf"));
    ASSERT_EQ(embedded.triangles.size(), 2u);
    ASSERT_EQ(embedded.surface.normals.size(), 2u);
    expectSameGeometry(embedded, loadGltf(g.writeGlb(dir)));

    MiniGltf external = g;
    external.bufferUri = "two triangles.bin";
    test::writeBytes(dir.file("two triangles.bin"), g.bin);
    external.bufferUri = "two%20triangles.bin"; // percent-encoded, as a URI is
    std::ofstream(dir.file("external.gltf")) << external.json();
    expectSameGeometry(embedded, loadGltf(dir.file("external.gltf")));

    // An escaped URI is left to tinygltf, which reads the same bytes.
    MiniGltf escaped = g;
    escaped.bufferUri = "sub\\/data.bin";
    std::filesystem::create_directories(dir.file("sub"));
    test::writeBytes(dir.file("sub/data.bin"), g.bin);
    std::ofstream(dir.file("escaped.gltf")) << escaped.json();
    expectSameGeometry(embedded, loadGltf(dir.file("escaped.gltf")));

    // The glTF-buffer media type, and a file longer than byteLength (its tail is not read).
    MiniGltf gltfBuffer = g;
    gltfBuffer.bufferUri = "data:application/gltf-buffer;base64," + test::base64(g.bin);
    std::ofstream(dir.file("gltf_buffer.gltf")) << gltfBuffer.json();
    expectSameGeometry(embedded, loadGltf(dir.file("gltf_buffer.gltf")));
    MiniGltf padded = g;
    padded.bufferUri = "padded.bin";
    std::vector<uint8_t> longer = g.bin;
    longer.resize(longer.size() + 100, 0xEE);
    test::writeBytes(dir.file("padded.bin"), longer);
    std::ofstream(dir.file("padded.gltf")) << padded.json();
    expectSameGeometry(embedded, loadGltf(dir.file("padded.gltf")));
}

std::string errorOf(const std::string& path) {
    try {
        loadGltf(path);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(loaded)";
}

TEST(BufferStreaming, ShortOrBrokenBuffersAreRefusedByName) {
    TempDir dir;
    MiniGltf g = twoTriangles();
    MiniGltf shortUri = g;
    std::vector<uint8_t> fewer(g.bin.begin(), g.bin.end() - 4);
    shortUri.bufferUri = "data:application/octet-stream;base64," + test::base64(fewer);
    std::ofstream(dir.file("short.gltf")) << shortUri.json();
    EXPECT_NE(errorOf(dir.file("short.gltf")).find("buffer 0: its data URI holds"),
              std::string::npos)
        << errorOf(dir.file("short.gltf"));

    MiniGltf broken = g;
    broken.bufferUri = "data:application/octet-stream;base64,AA*A";
    std::ofstream(dir.file("broken.gltf")) << broken.json();
    EXPECT_NE(errorOf(dir.file("broken.gltf")).find("not valid base64"), std::string::npos);

    MiniGltf shortFile = g;
    shortFile.bufferUri = "short.bin";
    test::writeBytes(dir.file("short.bin"), fewer);
    std::ofstream(dir.file("short_file.gltf")) << shortFile.json();
    EXPECT_NE(errorOf(dir.file("short_file.gltf")).find("'short.bin' holds"), std::string::npos)
        << errorOf(dir.file("short_file.gltf"));

    // A GLB whose buffer claims more than its BIN chunk holds.
    std::string json = g.json(true);
    const std::string length = "\"byteLength\":" + std::to_string(g.bin.size());
    json.replace(json.rfind(length), length.size(), "\"byteLength\":4096");
    test::writeBytes(dir.file("long.glb"), test::glbBytes(json, g.bin));
    EXPECT_NE(errorOf(dir.file("long.glb")).find("past the end of the BIN chunk"),
              std::string::npos)
        << errorOf(dir.file("long.glb"));
}

} // namespace
} // namespace wf
