// Compressed meshes made here, with Draco's and meshoptimizer's own encoders, load as the
// triangles of the uncompressed original (within quantization's moves): Draco (which reorders
// points and faces), meshopt as gltfpack writes it (EXT, GLB, quantized positions, octahedral
// normals, a fallback buffer) and as KHR in a .gltf (float positions through the exponential
// filter, index sequences). Cut or corrupted streams are refused in one line, never a crash.
#include <gtest/gtest.h>

#include <meshoptimizer.h>

#include <cmath>
#include <filesystem>

#include <glm/gtc/packing.hpp>

#include "compressed_gltf.h"
#include "draco_test_encoder.h"
#include "errors.h"
#include "scene/gltf/gltf_loader.h"

namespace wf {
namespace {

using test::Json;
namespace fs = std::filesystem;

// A bumpy 12 x 12 grid over [0, 1]^2: 144 vertices, 242 triangles, smooth normals.
struct Grid {
    std::vector<float> positions, normals; // 3 per vertex
    std::vector<uint32_t> indices;
    static constexpr int N = 12;
    Grid() {
        for (int y = 0; y < N; ++y) {
            for (int x = 0; x < N; ++x) {
                const float u = x / float(N - 1), v = y / float(N - 1);
                const float h = 0.15f * std::sin(6.0f * u) * std::cos(5.0f * v);
                const glm::vec3 n = glm::normalize(glm::vec3(
                    -0.9f * std::cos(6.0f * u) * std::cos(5.0f * v),
                    0.75f * std::sin(6.0f * u) * std::sin(5.0f * v), 1.0f));
                positions.insert(positions.end(), {u, v, h});
                normals.insert(normals.end(), {n.x, n.y, n.z});
            }
        }
        for (int y = 0; y + 1 < N; ++y) {
            for (int x = 0; x + 1 < N; ++x) {
                const uint32_t a = y * N + x, b = a + 1, c = a + N, d = c + 1;
                indices.insert(indices.end(), {a, b, d, a, d, c});
            }
        }
    }
    std::size_t vertices() const { return positions.size() / 3; }
};

using test::Document;
using test::encodeVertices;
using test::meshoptView;

// A folder per test: ctest runs these tests as parallel processes, and every test writes its
// own original.glb (one shared folder let one test read another's half-written file).
std::string tempFile(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / "wf_test_gltf_compression" /
                         ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::create_directories(dir);
    return (dir / name).string();
}

void primitive(Document& doc, int position, int normal, int indices, Json node = Json::object()) {
    const Json attributes = {{"POSITION", position}, {"NORMAL", normal}};
    const Json primitive = {{"attributes", attributes}, {"indices", indices}};
    doc.json["meshes"] =
        Json::array({Json::object({{"primitives", Json::array({primitive})}})});
    node["mesh"] = 0;
    doc.json["nodes"] = Json::array({node});
}

std::string writeOriginal(const Grid& grid) {
    Document doc;
    const auto plain = [&](const void* data, std::size_t size, std::size_t count,
                           const char* type, int componentType) {
        return doc.accessor({{"bufferView", doc.rawView(data, size)},
                             {"componentType", componentType},
                             {"count", count},
                             {"type", type}});
    };
    const int p = plain(grid.positions.data(), grid.positions.size() * 4, grid.vertices(),
                        "VEC3", 5126);
    const int n = plain(grid.normals.data(), grid.normals.size() * 4, grid.vertices(), "VEC3",
                        5126);
    const int i = plain(grid.indices.data(), grid.indices.size() * 4, grid.indices.size(),
                        "SCALAR", 5125);
    primitive(doc, p, n, i);
    return doc.write(tempFile("original.glb"));
}

glm::vec3 decodeNormal(uint32_t packed) {
    return gpu_types::octDecode(glm::unpackSnorm2x16(packed));
}

// Every loaded triangle matches one original triangle (the one of nearest centroid), with the
// same winding: corners within `tolerance` after a cyclic rotation, normals within
// `normalDegrees`. Draco reorders faces and rotates their corners, so order is not compared.
void expectSameTriangles(const Scene& actual, const Scene& expected, float tolerance,
                         float normalDegrees) {
    ASSERT_EQ(actual.triangles.size(), expected.triangles.size());
    ASSERT_EQ(actual.surface.normals.size(), actual.triangles.size());
    ASSERT_EQ(expected.surface.normals.size(), expected.triangles.size());
    const float cosLimit = std::cos(glm::radians(normalDegrees));
    std::vector<bool> used(expected.triangles.size(), false);
    float worst = 0.0f, worstCos = 1.0f;
    for (std::size_t t = 0; t < actual.triangles.size(); ++t) {
        const Triangle& a = actual.triangles[t];
        const glm::vec3 ca = (a.p0 + a.p1 + a.p2) / 3.0f;
        std::size_t best = 0;
        float bestDistance = INFINITY;
        for (std::size_t e = 0; e < expected.triangles.size(); ++e) {
            const Triangle& b = expected.triangles[e];
            const float d = glm::distance(ca, (b.p0 + b.p1 + b.p2) / 3.0f);
            if (d < bestDistance) {
                bestDistance = d;
                best = e;
            }
        }
        ASSERT_FALSE(used[best]) << "two triangles match original triangle " << best;
        used[best] = true;
        const Triangle& b = expected.triangles[best];
        const glm::vec3 pa[3] = {a.p0, a.p1, a.p2}, pb[3] = {b.p0, b.p1, b.p2};
        const auto& na = actual.surface.normals[t];
        const auto& nb = expected.surface.normals[best];
        const uint32_t qa[3] = {na.n0, na.n1, na.n2}, qb[3] = {nb.n0, nb.n1, nb.n2};
        int rotation = -1;
        for (int r = 0; r < 3 && rotation < 0; ++r) {
            bool same = true;
            for (int k = 0; k < 3; ++k) {
                same &= glm::distance(pa[k], pb[(k + r) % 3]) <= tolerance;
            }
            rotation = same ? r : -1;
        }
        ASSERT_GE(rotation, 0) << "triangle " << t << " has no corners matching triangle "
                               << best << " in the same winding";
        for (int k = 0; k < 3; ++k) {
            worst = std::max(worst, glm::distance(pa[k], pb[(k + rotation) % 3]));
            worstCos = std::min(worstCos, glm::dot(decodeNormal(qa[k]),
                                                   decodeNormal(qb[(k + rotation) % 3])));
        }
    }
    EXPECT_LE(worst, tolerance);
    EXPECT_GE(worstCos, cosLimit) << "normals differ by "
                                  << glm::degrees(std::acos(std::min(worstCos, 1.0f))) << " deg";
    ::testing::Test::RecordProperty("worst_corner_distance", std::to_string(worst));
}

// Draco data in buffer 0 behind bufferView 0; accessors without bufferView.
Document dracoDocument(const test::DracoOutput& encoded, int positionType, bool normalized,
                       Json node = Json::object()) {
    Document doc;
    doc.json["extensionsUsed"] = doc.json["extensionsRequired"] =
        Json::array({"KHR_draco_mesh_compression"});
    if (positionType != 5126) {
        doc.json["extensionsUsed"].push_back("KHR_mesh_quantization");
        doc.json["extensionsRequired"].push_back("KHR_mesh_quantization");
    }
    const int v = doc.rawView(encoded.bytes.data(), encoded.bytes.size());
    const int p = doc.accessor({{"componentType", positionType}, {"normalized", normalized},
                                {"count", encoded.points}, {"type", "VEC3"}});
    const int n = doc.accessor({{"componentType", 5126}, {"count", encoded.points},
                                {"type", "VEC3"}});
    const int i = doc.accessor({{"componentType", 5123}, {"count", encoded.faces * 3},
                                {"type", "SCALAR"}});
    primitive(doc, p, n, i, node);
    const Json draco = {
        {"bufferView", v},
        {"attributes", {{"POSITION", encoded.ids[0]}, {"NORMAL", encoded.ids[1]}}}};
    doc.json["meshes"][0]["primitives"][0]["extensions"] =
        Json::object({{"KHR_draco_mesh_compression", draco}});
    return doc;
}

test::DracoInput dracoInput(const Grid& grid, int positionBits, int normalBits) {
    test::DracoInput input;
    input.attributes.resize(2);
    input.attributes[0].floats = grid.positions;
    input.attributes[0].quantizationBits = positionBits;
    input.attributes[1].position = false;
    input.attributes[1].normal = true;
    input.attributes[1].floats = grid.normals;
    input.attributes[1].quantizationBits = normalBits;
    input.indices = grid.indices;
    return input;
}

TEST(GltfCompression, DracoMatchesTheOriginal) {
    const Grid grid;
    const Scene original = loadGltf(writeOriginal(grid));
    const test::DracoOutput encoded = test::encodeDracoMesh(dracoInput(grid, 14, 10));
    ASSERT_EQ(encoded.error, "");
    ASSERT_EQ(encoded.points, grid.vertices());
    for (const char* name : {"draco.glb", "draco.gltf"}) {
        SCOPED_TRACE(name);
        Document doc = dracoDocument(encoded, 5126, false);
        expectSameTriangles(loadGltf(doc.write(tempFile(name))), original, 1e-4f, 1.0f);
    }
}

// KHR_mesh_quantization under Draco: u16 positions stored losslessly as Draco integers, the
// accessor normalized and the node scaling them back, as quantizing exporters do.
TEST(GltfCompression, DracoWithQuantizedPositions) {
    const Grid grid;
    const Scene original = loadGltf(writeOriginal(grid));
    test::DracoInput input = dracoInput(grid, 0, 10);
    const float lo = -0.15f, range = 1.15f; // positions span [-0.15, 1] on every axis here
    input.attributes[0].floats.clear();
    for (float p : grid.positions) {
        input.attributes[0].u16.push_back(uint16_t(std::lround((p - lo) / range * 65535.0f)));
    }
    const test::DracoOutput encoded = test::encodeDracoMesh(input);
    ASSERT_EQ(encoded.error, "");
    Document doc = dracoDocument(encoded, 5123, true,
                                 {{"translation", {lo, lo, lo}}, {"scale", {range, range, range}}});
    expectSameTriangles(loadGltf(doc.write(tempFile("draco_quantized.glb"))), original, 2e-5f,
                        1.0f);
}

// gltfpack -cc's layout: u16 positions padded to 8 bytes, normalized, dequantized by the node;
// int8 normals through the octahedral filter; triangle-coded u16 indices; fallback buffer.
TEST(GltfCompression, MeshoptQuantizedAsGltfpackWritesIt) {
    const Grid grid;
    const Scene original = loadGltf(writeOriginal(grid));
    const std::size_t n = grid.vertices();
    const float lo = -0.15f, range = 1.15f;
    std::vector<uint16_t> positions(n * 4, 0);
    for (std::size_t i = 0; i < n * 3; ++i) {
        positions[i / 3 * 4 + i % 3] =
            uint16_t(std::lround((grid.positions[i] - lo) / range * 65535.0f));
    }
    std::vector<float> normals4(n * 4, 0.0f);
    for (std::size_t i = 0; i < n * 3; ++i) {
        normals4[i / 3 * 4 + i % 3] = grid.normals[i];
    }
    std::vector<int8_t> octahedral(n * 4);
    meshopt_encodeFilterOct(octahedral.data(), n, 4, 8, normals4.data());
    const std::vector<uint16_t> indices(grid.indices.begin(), grid.indices.end());
    std::vector<unsigned char> triangles(meshopt_encodeIndexBufferBound(indices.size(), n));
    triangles.resize(meshopt_encodeIndexBuffer(triangles.data(), triangles.size(),
                                               indices.data(), indices.size()));

    Document doc;
    const char* ext = "EXT_meshopt_compression";
    doc.json["extensionsUsed"] = doc.json["extensionsRequired"] =
        Json::array({ext, "KHR_mesh_quantization"});
    std::size_t fallback = 0;
    const int pv = meshoptView(doc, ext, encodeVertices(positions.data(), n, 8), 8, n,
                               "ATTRIBUTES", nullptr, fallback);
    const int nv = meshoptView(doc, ext, encodeVertices(octahedral.data(), n, 4), 4, n,
                               "ATTRIBUTES", "OCTAHEDRAL", fallback);
    const int iv = meshoptView(doc, ext, triangles, 2, indices.size(), "TRIANGLES", nullptr,
                               fallback);
    const Json fallbackBuffer = Json::object({{"fallback", true}});
    doc.moreBuffers.push_back(
        {{"byteLength", fallback}, {"extensions", Json::object({{ext, fallbackBuffer}})}});
    const int p = doc.accessor({{"bufferView", pv}, {"componentType", 5123},
                                {"normalized", true}, {"count", n}, {"type", "VEC3"}});
    const int nn = doc.accessor({{"bufferView", nv}, {"componentType", 5120},
                                 {"normalized", true}, {"count", n}, {"type", "VEC3"}});
    const int i = doc.accessor({{"bufferView", iv}, {"componentType", 5123},
                                {"count", indices.size()}, {"type", "SCALAR"}});
    primitive(doc, p, nn, i, {{"translation", {lo, lo, lo}}, {"scale", {range, range, range}}});
    // 16-bit positions move corners by up to range / 2^17; 8-bit octahedral normals by ~1 deg.
    expectSameTriangles(loadGltf(doc.write(tempFile("meshopt_quantized.glb"))), original, 2e-5f,
                        2.0f);
}

// KHR in a .gltf: float positions through the exponential filter (lossless at 24 mantissa
// bits), float normals unfiltered, indices coded as a sequence.
TEST(GltfCompression, MeshoptKhrFloatsInGltf) {
    const Grid grid;
    const Scene original = loadGltf(writeOriginal(grid));
    const std::size_t n = grid.vertices();
    std::vector<uint32_t> exponential(n * 3);
    meshopt_encodeFilterExp(exponential.data(), n, 12, 24, grid.positions.data());
    std::vector<unsigned char> sequence(
        meshopt_encodeIndexSequenceBound(grid.indices.size(), n));
    sequence.resize(meshopt_encodeIndexSequence(sequence.data(), sequence.size(),
                                                grid.indices.data(), grid.indices.size()));
    Document doc;
    const char* ext = "KHR_meshopt_compression";
    doc.json["extensionsUsed"] = doc.json["extensionsRequired"] = Json::array({ext});
    std::size_t fallback = 0;
    const int pv = meshoptView(doc, ext, encodeVertices(exponential.data(), n, 12), 12, n,
                               "ATTRIBUTES", "EXPONENTIAL", fallback);
    const int nv = meshoptView(doc, ext, encodeVertices(grid.normals.data(), n, 12), 12, n,
                               "ATTRIBUTES", nullptr, fallback);
    const int iv = meshoptView(doc, ext, sequence, 4, grid.indices.size(), "INDICES", nullptr,
                               fallback);
    doc.moreBuffers.push_back(Json::object({{"byteLength", fallback}}));
    const int p = doc.accessor({{"bufferView", pv}, {"componentType", 5126}, {"count", n},
                                {"type", "VEC3"}});
    const int nn = doc.accessor({{"bufferView", nv}, {"componentType", 5126}, {"count", n},
                                 {"type", "VEC3"}});
    const int i = doc.accessor({{"bufferView", iv}, {"componentType", 5125},
                                {"count", grid.indices.size()}, {"type", "SCALAR"}});
    primitive(doc, p, nn, i);
    // Normals exact (the dot of equal unit vectors rounds to within 0.1 deg of 1).
    expectSameTriangles(loadGltf(doc.write(tempFile("meshopt_khr.gltf"))), original, 1e-6f, 0.1f);
}

// Loading must end in a scene or one InputError line; anything else (a crash, another
// exception) fails the test, and the sanitizer build sees every read.
bool refusedInOneLine(const std::string& path) {
    try {
        loadGltf(path);
        return false;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.what()).rfind(path + ": ", 0), 0u) << e.what();
        return true;
    }
}

TEST(GltfCompression, CutOrCorruptedStreamsAreRefusedCleanly) {
    const Grid grid;
    const test::DracoOutput encoded = test::encodeDracoMesh(dracoInput(grid, 14, 10));
    ASSERT_EQ(encoded.error, "");
    const std::size_t size = encoded.bytes.size();
    // Every cut of the Draco stream is refused: its decoder needs every byte it wrote.
    for (std::size_t cut = 0; cut < size; cut += std::max<std::size_t>(1, size / 40)) {
        test::DracoOutput shorter = encoded;
        shorter.bytes.resize(cut);
        Document doc = dracoDocument(shorter, 5126, false);
        EXPECT_TRUE(refusedInOneLine(doc.write(tempFile("draco_cut.glb"))))
            << "cut at " << cut;
    }
    // Flipped bytes may still decode (to other triangles); then they must load as such.
    std::size_t refused = 0, tried = 0;
    for (std::size_t at = 0; at < size; at += std::max<std::size_t>(1, size / 60), ++tried) {
        test::DracoOutput flipped = encoded;
        flipped.bytes[at] ^= 0x5a;
        Document doc = dracoDocument(flipped, 5126, false);
        refused += refusedInOneLine(doc.write(tempFile("draco_flipped.glb")));
    }
    EXPECT_GT(refused, 0u) << "of " << tried;

    // meshopt: the vertex codec finds its tail from the end, so a cut stream either fails to
    // decode or decodes other values, which then must be finite to load.
    std::vector<unsigned char> vertices =
        encodeVertices(grid.positions.data(), grid.vertices(), 12);
    for (std::size_t cut = 0; cut < vertices.size();
         cut += std::max<std::size_t>(1, vertices.size() / 40)) {
        Document doc;
        doc.json["extensionsUsed"] = doc.json["extensionsRequired"] =
            Json::array({"EXT_meshopt_compression"});
        std::size_t fallback = 0;
        const std::vector<unsigned char> part(vertices.begin(), vertices.begin() + long(cut));
        const int pv = meshoptView(doc, "EXT_meshopt_compression", part, 12, grid.vertices(),
                                   "ATTRIBUTES", nullptr, fallback);
        doc.moreBuffers.push_back(Json::object({{"byteLength", fallback}}));
        const int p = doc.accessor({{"bufferView", pv}, {"componentType", 5126},
                                    {"count", grid.vertices()}, {"type", "VEC3"}});
        const Json attributes = Json::object({{"POSITION", p}});
        const Json primitive = Json::object({{"attributes", attributes}});
        doc.json["meshes"] =
            Json::array({Json::object({{"primitives", Json::array({primitive})}})});
        doc.json["nodes"] = Json::array({Json::object({{"mesh", 0}})});
        refusedInOneLine(doc.write(tempFile("meshopt_cut.glb")));
    }
}

} // namespace
} // namespace wf
