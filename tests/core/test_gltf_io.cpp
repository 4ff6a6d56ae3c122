#include "core/io/gltf_io.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cstring>
#include <fstream>
#include <random>
#include <set>

#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/support/error.h"
#include "tests/support/random_spd.h"
#include "tests/support/temp_dir.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/hand_made_gltf.h"

namespace gps {
namespace {

using nlohmann::json;
using test::HandMade;
using test::split_cube;

// The corners of each face of a mesh as a set of sorted triples after fan triangulation, in positions
// rounded to float: comparable between a mesh and its glTF copy whatever the vertex order.
std::multiset<std::vector<float>> triangles_by_position(const CovarianceMesh& m) {
  std::multiset<std::vector<float>> out;
  for (size_t f = 0; f < m.n_faces(); ++f) {
    std::vector<Vec3> corners;
    for (const int v : m.face(f)) corners.push_back(m.mean(size_t(v)));
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      // Rotated so that the smallest corner leads: the same triangle, turning the same way, compares equal.
      std::vector<std::vector<float>> t;
      for (const Vec3& p : {corners[0], corners[k], corners[k + 1]})
        t.push_back({float(p.x()), float(p.y()), float(p.z())});
      std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
      std::vector<float> flat;
      for (const auto& c : t) flat.insert(flat.end(), c.begin(), c.end());
      out.insert(flat);
    }
  }
  return out;
}

size_t n_triangles(const CovarianceMesh& m) {
  size_t n = 0;
  for (size_t f = 0; f < m.n_faces(); ++f) n += size_t(m.face_size(f) - 2);
  return n;
}

CovarianceMesh torus_with_random_covariances() {
  CovarianceMesh m = make_sample("torus");
  std::mt19937 rng(7);
  for (auto& c : m.covariances) c = test::random_spd(rng, 9e-3) / 9.0;
  return m;
}

void expect_same_as_written(const CovarianceMesh& written, const CovarianceMesh& read) {
  ASSERT_EQ(read.n_vertices(), written.n_vertices());
  EXPECT_EQ(read.n_faces(), n_triangles(written));
  EXPECT_EQ(triangles_by_position(read), triangles_by_position(written));
  // The writer keeps the vertex order: each Gaussian to float precision.
  for (size_t i = 0; i < written.n_vertices(); ++i) {
    EXPECT_LE((read.mean(i) - written.mean(i)).cwiseAbs().maxCoeff(), 1e-7 * (1 + written.mean(i).norm())) << i;
    const Mat3& a = written.covariance(i);
    EXPECT_LE((read.covariance(i) - a).cwiseAbs().maxCoeff(), 1e-7 * a.cwiseAbs().maxCoeff()) << i;
  }
}

TEST(GltfIo, CovarianceTorusRoundTripsThroughGlbAndGltf) {
  test::TempDir dir;
  const CovarianceMesh torus = torus_with_random_covariances();
  for (const char* name : {"torus.glb", "torus.gltf"}) {
    write_mesh(dir.file(name), torus);
    std::vector<std::string> notes;
    const CovarianceMesh read = read_mesh(dir.file(name), {}, nullptr, &notes);
    expect_same_as_written(torus, read);
    EXPECT_TRUE(notes.empty()) << notes.front();
  }
  std::ifstream in(dir.file("torus.gltf"));
  const json j = json::parse(in);
  EXPECT_EQ(j["buffers"][0]["uri"].get<std::string>().rfind("data:application/octet-stream;base64,", 0), 0u);
}

// Two tetrahedra meeting at one point, as a repair leaves a pinch vertex: two vertices at one
// position. A covariance glTF keeps them apart, so the mesh reads back as written (welded, it would be
// refused as pinched).
TEST(GltfIo, CovarianceVerticesAtOnePositionStayApart) {
  test::TempDir dir;
  const std::vector<Vec3> p = {Vec3(0, 0, 0), Vec3(1, 0, 0),  Vec3(0, 1, 0),  Vec3(0, 0, 1),
                               Vec3(0, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, -1), Vec3(0, -1, 0)};
  std::vector<std::vector<int>> faces;
  for (const int b : {0, 4})
    faces.insert(faces.end(), {{b, b + 2, b + 1}, {b, b + 1, b + 3}, {b, b + 3, b + 2}, {b + 1, b + 2, b + 3}});
  const CovarianceMesh pinched =
      make_covariance_mesh(p, std::vector<Mat3>(8, 0.01 * Mat3::Identity()), faces, "pinched");
  for (const char* name : {"pinched.glb", "pinched.gltf"}) {
    write_mesh(dir.file(name), pinched);
    expect_same_as_written(pinched, read_mesh(dir.file(name)));
  }
}

// What a viewer needs of the JSON (glTF 2.0 §3.6, §3.7): version, one triangle primitive, POSITION
// with min and max, unit normals, the covariance as MAT3 float, buffer views with their targets.
TEST(GltfIo, GlbJsonChunkIsWhatTheSpecificationAsks) {
  test::TempDir dir;
  const CovarianceMesh cube = make_sample("cube");
  write_mesh(dir.file("cube.glb"), cube);
  std::ifstream in(dir.file("cube.glb"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GE(bytes.size(), 20u);
  uint32_t header[5];
  std::memcpy(header, bytes.data(), sizeof header);
  EXPECT_EQ(std::string(bytes.data(), 4), "glTF");
  EXPECT_EQ(header[1], 2u);
  EXPECT_EQ(header[2], bytes.size());
  EXPECT_EQ(header[3] % 4, 0u);  // chunks are 4-byte aligned
  EXPECT_EQ(std::string(bytes.data() + 16, 4), "JSON");
  const json j = json::parse(bytes.substr(20, header[3]));
  EXPECT_EQ(j["asset"]["version"], "2.0");
  EXPECT_EQ(j["scene"], 0);
  const json& primitive = j["meshes"][0]["primitives"][0];
  EXPECT_EQ(primitive.value("mode", 4), 4);
  const json& position = j["accessors"][primitive["attributes"]["POSITION"].get<int>()];
  EXPECT_EQ(position["componentType"], 5126);
  EXPECT_EQ(position["type"], "VEC3");
  EXPECT_EQ(position["count"], 8);
  EXPECT_EQ(position["min"], json::array({-1.0, -1.0, -1.0}));
  EXPECT_EQ(position["max"], json::array({1.0, 1.0, 1.0}));
  const json& covariance = j["accessors"][primitive["attributes"]["_COVARIANCE"].get<int>()];
  EXPECT_EQ(covariance["type"], "MAT3");
  EXPECT_EQ(covariance["componentType"], 5126);
  const json& indices = j["accessors"][primitive["indices"].get<int>()];
  EXPECT_EQ(indices["componentType"], 5125);
  EXPECT_EQ(indices["count"], 36);  // 6 quads, 2 triangles each
  EXPECT_EQ(j["bufferViews"][indices["bufferView"].get<int>()]["target"], 34963);
  EXPECT_EQ(j["bufferViews"][position["bufferView"].get<int>()]["target"], 34962);
  for (const json& view : j["bufferViews"]) EXPECT_EQ(view.value("byteOffset", 0) % 4, 0);
  // Normals are unit vectors: at a cube's corner, along the diagonal.
  const CovarianceMesh read = read_mesh(dir.file("cube.glb"));
  const GltfTriangles t = gltf_triangles_of(cube);
  for (const Vec3& n : t.normals) {
    EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(n.x()), 1 / std::sqrt(3.0), 1e-12);
  }
  EXPECT_EQ(read.n_vertices(), 8u);
}

TEST(GltfIo, SeamSplitCubeWeldsTo8VerticesInGlbAndGltfWithBinFile) {
  test::TempDir dir;
  const HandMade cube = split_cube();
  dir.write("cube.glb", cube.glb());
  cube.write_gltf(dir, "cube.gltf", "cube data.bin");
  for (const char* name : {"cube.glb", "cube.gltf"}) {
    const CovarianceMesh m = read_mesh(dir.file(name));
    EXPECT_EQ(m.n_vertices(), 8u) << name;
    EXPECT_EQ(m.n_faces(), 12u) << name;
    // Closed: every edge has two faces, and the faces turn outward (positive volume).
    for (size_t e = 0; e < m.n_edges(); ++e) EXPECT_FALSE(m.is_boundary_edge(e));
    double volume = 0;
    for (size_t f = 0; f < m.n_faces(); ++f) {
      std::vector<Vec3> c;
      for (const int v : m.face(f)) c.push_back(m.mean(size_t(v)));
      volume += c[0].dot(c[1].cross(c[2])) / 6;
    }
    EXPECT_DOUBLE_EQ(volume, 8.0) << name;
    // Inferred as for a plain mesh: the same Gaussians as the 8-vertex cube's triangles would get.
    for (const Mat3& s : m.covariances) EXPECT_TRUE(is_spd(s));
  }
}

TEST(GltfIo, NodeTransformsThroughTheHierarchyPlaceEachInstance) {
  test::TempDir dir;
  HandMade h = split_cube();
  // Node 0: translation, rotation and scale, its child node 1 translated again; node 2 by a matrix.
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.5, Vec3(1, 2, 3).normalized()));
  h.j["nodes"] = {{{"translation", {10, 0, 0}},
                   {"rotation", {q.x(), q.y(), q.z(), q.w()}},
                   {"scale", {2, 3, 4}},
                   {"children", {1}}},
                  {{"translation", {0, 5, 0}}, {"mesh", 0}},
                  {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -20, 0, 0, 1}}, {"mesh", 0}}};
  h.j["scenes"] = {{{"nodes", {0, 2}}}};
  dir.write("two.glb", h.glb());
  const CovarianceMesh m = read_mesh(dir.file("two.glb"));
  ASSERT_EQ(m.n_vertices(), 16u);
  EXPECT_EQ(m.n_faces(), 24u);
  // World = T R S of node 0 times node 1's translation (glTF 2.0 §3.5.3).
  const Eigen::Affine3d node0 = Eigen::Translation3d(10, 0, 0) * q * Eigen::Scaling(Vec3(2, 3, 4));
  const Eigen::Affine3d first = node0 * Eigen::Translation3d(0, 5, 0);
  std::vector<Vec3> expected;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 p(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1);
    expected.push_back(first * p);
    expected.push_back(p + Vec3(-20, 0, 0));
  }
  for (const Vec3& e : expected) {
    double nearest = 1e9;
    for (size_t i = 0; i < m.n_vertices(); ++i) nearest = std::min(nearest, (m.mean(i) - e).norm());
    EXPECT_LT(nearest, 1e-12) << e.transpose();
  }
}

// A node that mirrors (a negative scale, or a matrix of negative determinant) turns the winding around,
// as glTF 2.0 says: the faces are read reversed and the solid stays outward.
TEST(GltfIo, AMirroringNodeKeepsTheFacesOutward) {
  test::TempDir dir;
  for (const nlohmann::json& node :
       {nlohmann::json{{"mesh", 0}}, nlohmann::json{{"scale", {-1, 1, 1}}, {"mesh", 0}},
        nlohmann::json{{"scale", {-1, -1, -1}}, {"mesh", 0}},
        nlohmann::json{{"matrix", {1, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 5, 0, 0, 1}}, {"mesh", 0}}}) {
    HandMade h = split_cube();
    h.j["nodes"] = nlohmann::json::array({node});
    dir.write("m.glb", h.glb());
    const CovarianceMesh m = read_mesh(dir.file("m.glb"));
    EXPECT_NEAR(test::signed_volume(m), 8.0, 1e-12) << node.dump();
  }
}

TEST(GltfIo, CovariancesFollowTheNodeTransform) {
  test::TempDir dir;
  HandMade h = split_cube();
  // Every corner's Gaussian 0.01 I with a correlation of x and z; the node rotates and scales it.
  Mat3 sigma = 0.01 * Mat3::Identity();
  sigma(0, 2) = sigma(2, 0) = 0.004;
  h.add_covariances(std::vector<Mat3>(24, sigma));
  const Eigen::Quaterniond q(Eigen::AngleAxisd(1.0, Vec3(0, 1, 1).normalized()));
  h.j["nodes"] = {{{"rotation", {q.x(), q.y(), q.z(), q.w()}}, {"scale", {2, 1, 0.5}}, {"mesh", 0}}};
  dir.write("gauss.glb", h.glb());
  const CovarianceMesh m = read_mesh(dir.file("gauss.glb"));
  ASSERT_EQ(m.n_vertices(), 8u);
  // A Σ Aᵀ with A = R S, Σ as the file's floats give it.
  const Mat3 a = q.toRotationMatrix() * Vec3(2, 1, 0.5).asDiagonal();
  const Mat3 expected = a * sigma.cast<float>().cast<double>() * a.transpose();
  for (const Mat3& c : m.covariances) EXPECT_LT((c - expected).cwiseAbs().maxCoeff(), 1e-15) << c;
}

// A covariance symmetric only within rounding is kept as the check read it (its lower triangle), so
// that a save writes what was accepted: here the upper triangle's tiny xz would make the saved Σ one
// whose smallest eigenvalue (1e-38 of its largest) the check no longer resolves from zero.
TEST(GltfIo, ANearlySymmetricCovarianceIsKeptAsCheckedAndSavesAsItLoads) {
  test::TempDir dir;
  HandMade h = split_cube();
  std::vector<Mat3> sigmas(24, Mat3::Identity());
  sigmas[5](1, 1) = 1.1754943508222875e-38;
  sigmas[5](0, 2) = 8.8e-44;  // the upper triangle's xz
  h.add_covariances(sigmas);
  dir.write("near.glb", h.glb());
  const CovarianceMesh m = read_mesh(dir.file("near.glb"));
  for (const Mat3& c : m.covariances) EXPECT_EQ(c, c.transpose()) << c;
  for (const auto& [name, binary] :
       {std::pair{"near.ply", true}, {"near_ascii.ply", false}, {"near.obj", false}, {"near_again.glb", false}}) {
    write_mesh(dir.file(name), m, binary);
    EXPECT_NO_THROW(read_mesh(dir.file(name))) << name;
  }
}

TEST(GltfIo, StripAndFanPrimitivesGiveTheirTriangles) {
  test::TempDir dir;
  HandMade h;
  // A square as a fan of 2 triangles and, beside it, a strip of 2 triangles: 4 + 4 vertices.
  h.append(std::vector<float>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 0, 0, 6, 0, 0, 5, 1, 0, 6, 1, 0});
  h.j = {{"asset", {{"version", "2.0"}}},
         {"bufferViews", {{{"buffer", 0}, {"byteLength", 96}}}},
         {"accessors",
          {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
           {{"bufferView", 0}, {"byteOffset", 48}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}}}},
         {"meshes",
          {{{"primitives",
             {{{"attributes", {{"POSITION", 0}}}, {"mode", 6}}, {{"attributes", {{"POSITION", 1}}}, {"mode", 5}}}}}}}};
  dir.write("strips.glb", h.glb());
  const CovarianceMesh m = read_mesh(dir.file("strips.glb"));
  EXPECT_EQ(m.n_vertices(), 8u);
  EXPECT_EQ(m.n_faces(), 4u);
  // All four turn the same way (+z), the strip's second one reversed as the specification asks.
  for (size_t f = 0; f < m.n_faces(); ++f) {
    std::vector<Vec3> c;
    for (const int v : m.face(f)) c.push_back(m.mean(size_t(v)));
    EXPECT_GT((c[1] - c[0]).cross(c[2] - c[0]).z(), 0.0);
  }
}

// The one-line message read_mesh gives for the file, or "" where it reads.
std::string refusal(const std::string& path) {
  try {
    read_mesh(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void expect_refused(const std::string& path, const std::string& words) {
  const std::string why = refusal(path);
  EXPECT_NE(why.find(path), std::string::npos) << why;
  EXPECT_NE(why.find(words), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

TEST(GltfIo, MalformedFilesAreRefusedInOneLineNamingFileAndElement) {
  test::TempDir dir;
  const HandMade cube = split_cube();
  const std::string glb = cube.glb();
  expect_refused(dir.write("cut.glb", glb.substr(0, glb.size() - 10)), "truncated");
  expect_refused(dir.write("head.glb", glb.substr(0, 7)), "truncated");
  // A BIN chunk that claims its own header's bytes past the end of the file (as many as tinygltf would read).
  for (const uint32_t over : {4u, 8u}) {
    const std::string overclaiming = cube.glb(over);
    expect_refused(dir.write("over.glb", overclaiming),
                   "its BIN chunk ends at byte " + std::to_string(overclaiming.size() + over));
  }
  std::string no_room = glb.substr(0, glb.size() - cube.bin.size() - 4);
  const uint32_t length = uint32_t(no_room.size());
  std::memcpy(no_room.data() + 8, &length, 4);
  expect_refused(dir.write("room.glb", no_room), "4 bytes after its JSON chunk, too few for a chunk's header");
  expect_refused(dir.write("junk.gltf", "not json"), "neither a .glb");
  expect_refused(dir.write("bad.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [ }"),
                 "bad.gltf: is not valid glTF JSON (line 1, column 43)");
  const std::string buffers = "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"byteLength\": 12, \"uri\": ";
  expect_refused(dir.write("short.gltf", buffers + "\"data:application/octet-stream;base64,AAAA\"}]}"),
                 "short.gltf: has a buffer whose embedded data (its data: URI) is not base64 or does not hold its "
                 "byteLength in bytes");
  expect_refused(
      dir.write("gone.gltf", buffers + "\"gone.bin\"}]}"),
      "gone.gltf: names a buffer file 'gone.bin' that is not there (buffer files are read from the .gltf's folder)");
  // tinygltf's own words were shown for these.
  expect_refused(dir.write("empty.gltf", "{}"), "empty.gltf: is too short to be a glTF file");
  expect_refused(dir.write("unversioned.gltf", "{\"scenes\": []}"), "unversioned.gltf: has no \"asset\" object");
  expect_refused(dir.write("stride.gltf", buffers + "\"data:application/octet-stream;base64,AAAAAAAAAAAAAAAA\"}], "
                                                    "\"bufferViews\": [{\"buffer\": 0, \"byteLength\": 12, "
                                                    "\"byteStride\": 256}]}"),
                 "stride.gltf: has a bufferView whose byteStride is not a multiple of 4 from 4 to 252 (glTF's rule), "
                 "got 256");

  HandMade past = cube;
  past.j["accessors"][1]["count"] = 40;  // 80 bytes of a 72-byte view
  expect_refused(dir.write("past.glb", past.glb()),
                 "mesh 0 primitive 0: indices accessor 1 reads past its buffer view");

  HandMade missing = cube;
  missing.j["meshes"][0]["primitives"][0]["indices"] = 7;
  expect_refused(dir.write("missing.glb", missing.glb()),
                 "mesh 0 primitive 0: indices names accessor 7, which is not in the file");

  HandMade bad_index = cube;
  const uint16_t big = 24;  // the last index: the buffer's last 2 bytes (72 bytes of indices need no padding)
  std::memcpy(bad_index.bin.data() + bad_index.bin.size() - 2, &big, 2);
  expect_refused(dir.write("index.glb", bad_index.glb()), "mesh 0 primitive 0: index 35 is 24, past its 24 positions");

  HandMade points = cube;
  points.j["meshes"][0]["primitives"][0]["mode"] = 0;
  expect_refused(dir.write("points.glb", points.glb()), "has no triangles");

  HandMade no_position = cube;
  no_position.j["meshes"][0]["primitives"][0]["attributes"] = {{"NORMAL", 0}};
  expect_refused(dir.write("normal.glb", no_position.glb()), "mesh 0 primitive 0: has no POSITION attribute");

  HandMade loop = cube;
  loop.j["nodes"] = {{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}};
  expect_refused(dir.write("loop.glb", loop.glb()), "node 0 is reached twice");

  HandMade no_bin = cube;
  no_bin.write_gltf(dir, "nobin.gltf", "nobin.bin");
  std::filesystem::remove(dir.file("nobin.bin"));
  expect_refused(dir.file("nobin.gltf"), "nobin.gltf: ");
}

TEST(GltfIo, UnwritableCovarianceLeavesTheFileAsItWas) {
  test::TempDir dir;
  CovarianceMesh cube = make_sample("cube");
  const std::string path = dir.write("cube.glb", "old contents");
  // Positive definite in double, singular once rounded to float.
  cube.covariances[3] = Mat3::Identity();
  cube.covariances[3](0, 1) = cube.covariances[3](1, 0) = 1 - 1e-10;
  cube.covariances[3] *= 1e-2;
  ASSERT_TRUE(is_spd(cube.covariances[3]));
  try {
    write_mesh(path, cube);
    FAIL() << "written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 3 covariance rounded to float"), std::string::npos) << e.what();
  }
  std::ifstream in(path);
  EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), "old contents");
}

// The split cube with its positions as integers (KHR_mesh_quantization): each of ±1 written as `one` and
// `minus_one`, each vertex padded to 4-byte alignment, as the extension asks.
template <class T>
HandMade quantized_cube(int component_type, bool normalized, T minus_one, T one) {
  HandMade h = split_cube();
  std::vector<float> floats(72);
  std::memcpy(floats.data(), h.bin.data(), 72 * sizeof(float));
  const size_t stride = (3 * sizeof(T) + 3) / 4 * 4;
  std::string positions(24 * stride, '\0');
  for (size_t i = 0; i < 72; ++i) {
    const T value = floats[i] > 0 ? one : minus_one;
    std::memcpy(positions.data() + (i / 3) * stride + (i % 3) * sizeof(T), &value, sizeof(T));
  }
  const size_t offset = h.bin.size();
  h.bin += positions;
  h.j["bufferViews"].push_back(
      {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", positions.size()}, {"byteStride", stride}});
  json& accessor = h.j["accessors"][0];
  accessor["bufferView"] = h.j["bufferViews"].size() - 1;
  accessor["componentType"] = component_type;
  accessor["normalized"] = normalized;
  accessor["min"] = {minus_one, minus_one, minus_one};
  accessor["max"] = {one, one, one};
  h.j["extensionsUsed"] = {"KHR_mesh_quantization"};
  h.j["extensionsRequired"] = {"KHR_mesh_quantization"};
  return h;
}

TEST(GltfIo, QuantizedPositionsAreReadAsTheirNodeScalesThem) {
  test::TempDir dir;
  // Normalised shorts: ±32767 is ±1. Unsigned bytes 0 and 2, placed by the node's translation by −1. Signed
  // bytes ±1 as they are.
  std::vector<HandMade> cubes = {quantized_cube<int16_t>(5122, true, -32767, 32767),
                                 quantized_cube<uint8_t>(5121, false, 0, 2),
                                 quantized_cube<int8_t>(5120, false, -1, 1)};
  cubes[1].j["nodes"][0]["translation"] = {-1, -1, -1};
  for (size_t i = 0; i < cubes.size(); ++i) {
    const std::string name = "q" + std::to_string(i) + ".glb";
    const CovarianceMesh m = read_mesh(dir.write(name, cubes[i].glb()));
    ASSERT_EQ(m.n_vertices(), 8u) << name;
    EXPECT_EQ(m.n_faces(), 12u) << name;
    for (size_t v = 0; v < m.n_vertices(); ++v)
      EXPECT_EQ(m.mean(v).cwiseAbs(), Vec3::Ones()) << name << " vertex " << v;
    test::expect_closed_outward(m, 8, 12);
  }
}

TEST(GltfIo, RequiredExtensionsItDoesNotReadAreRefusedByName) {
  test::TempDir dir;
  HandMade h = split_cube();
  // Materials and lights change only how a surface looks: a file that requires them is read.
  h.j["extensionsRequired"] = {"KHR_materials_pbrSpecularGlossiness", "KHR_texture_transform", "KHR_lights_punctual"};
  EXPECT_EQ(read_mesh(dir.write("looks.glb", h.glb())).n_vertices(), 8u);
  // A compressed file's accessors have no buffer views of their own: refused by the extension, not by them.
  h.j["extensionsRequired"] = {"KHR_texture_transform", "KHR_draco_mesh_compression"};
  h.j["accessors"][0].erase("bufferView");
  expect_refused(dir.write("draco.glb", h.glb()),
                 "draco.glb: requires the glTF extension 'KHR_draco_mesh_compression', which gpsurf does not read "
                 "(export the file without mesh compression)");
  h.write_gltf(dir, "draco.gltf", "draco.bin");
  expect_refused(dir.file("draco.gltf"), "draco.gltf: requires the glTF extension 'KHR_draco_mesh_compression'");
  h.j["extensionsRequired"] = {"EXT_meshopt_compression"};
  expect_refused(dir.write("meshopt.glb", h.glb()), "requires the glTF extension 'EXT_meshopt_compression'");
  h.j["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  expect_refused(dir.write("instancing.glb", h.glb()),
                 "instancing.glb: requires the glTF extension 'EXT_mesh_gpu_instancing', which gpsurf does not read");
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

TEST(GltfIo, DeeplyNestedJsonIsRefusedBeforeTinygltfRecursesIntoIt) {
  // tinygltf reads "extras" recursively: 20,000 levels overflowed its stack.
  test::TempDir dir;
  HandMade h = split_cube();
  const std::string deep = std::string(20000, '[') + std::string(20000, ']');
  HandMade shallow = h;
  shallow.j["extras"] = json::array({json::array({json::array()})});
  EXPECT_EQ(read_mesh(dir.write("shallow.glb", shallow.glb())).n_vertices(), 8u);
  json with_buffer = h.j;
  with_buffer["buffers"] = json::array({{{"byteLength", h.bin.size()}, {"uri", "cube.bin"}}});
  dir.write("cube.bin", h.bin);
  std::string gltf = with_buffer.dump();
  gltf.insert(gltf.size() - 1, ",\"extras\":" + deep);
  expect_refused(dir.write("deep.gltf", gltf), "deep.gltf: is glTF JSON nested more than 64 levels deep");
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

TEST(GltfIo, AFaceIsFannedSoThatTheFileReadsBack) {
  // A quad folded onto the triangle beside it: fanned from its first corner, its diagonal 0–2 was the
  // triangle's edge, and the file read back with a duplicate face.
  const CovarianceMesh fold =
      make_covariance_mesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5}},
                           std::vector<Mat3>(4, 0.01 * Mat3::Identity()), {{0, 1, 2, 3}, {0, 3, 2}});
  test::TempDir dir;
  for (const char* name : {"fold.glb", "fold.gltf"}) {
    write_mesh(dir.file(name), fold);
    const CovarianceMesh back = read_mesh(dir.file(name));
    EXPECT_EQ(back.n_vertices(), 4u) << name;
    EXPECT_EQ(back.n_faces(), 3u) << name;
  }
}

// A U-shaped octagon: fanned from one corner, its triangles overlapped and some turned over.
TEST(GltfIo, ANonConvexFaceIsCutIntoTrianglesInsideIt) {
  const CovarianceMesh u =
      make_covariance_mesh({{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}},
                           std::vector<Mat3>(8, 0.01 * Mat3::Identity()), {{0, 1, 2, 3, 4, 5, 6, 7}});
  test::TempDir dir;
  write_mesh(dir.file("u.glb"), u);
  const CovarianceMesh back = read_mesh(dir.file("u.glb"));
  ASSERT_EQ(back.n_faces(), 6u);
  double area = 0;
  for (size_t f = 0; f < back.n_faces(); ++f) {
    const auto t = back.face(f);
    const double z = (back.mean(size_t(t[1])) - back.mean(size_t(t[0])))
                         .cross(back.mean(size_t(t[2])) - back.mean(size_t(t[0])))
                         .z();
    EXPECT_GT(z, 0.0) << "triangle " << f << " turns over";
    area += z / 2;
  }
  EXPECT_NEAR(area, 7.0, 1e-12);  // the U's area: no two triangles overlap
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// Two closed cubes side by side, sharing the plane x = 1, placed by two nodes: each has vertices of its
// own, as two OBJ objects with their own vertex lists, and each is still welded at its seams (8
// vertices, not 24). Welded across them, the face between them read twice and its edges as fins.
TEST(GltfIo, TouchingInstancesStayApartEachWeldedAtItsSeams) {
  test::TempDir dir;
  HandMade nodes = split_cube();
  nodes.j["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {2, 0, 0}}}};
  nodes.j["scenes"] = {{{"nodes", {0, 1}}}};
  const CovarianceMesh m = read_mesh(dir.write("nodes.glb", nodes.glb()));
  test::expect_closed_outward(m, 16, 24);
  EXPECT_EQ(test::shape_of(m).euler(), 4);  // two spheres
  EXPECT_NEAR(test::signed_volume(m), 16.0, 1e-12);
  size_t on_the_plane = 0;
  for (size_t v = 0; v < m.n_vertices(); ++v) on_the_plane += m.mean(v).x() == 1.0;
  EXPECT_EQ(on_the_plane, 8u);  // the 4 corners there once for each cube
}

// One cube as two primitives of its mesh (as exporters split one by material), three faces each: their
// borders' corners are welded, and it reads as the closed cube.
TEST(GltfIo, PrimitivesOfOneMeshAreWeldedAtTheirBorders) {
  test::TempDir dir;
  HandMade h = split_cube();
  std::vector<uint16_t> indices(36);
  std::memcpy(indices.data(), h.bin.data() + 24 * 3 * sizeof(float), indices.size() * sizeof(uint16_t));
  json first = h.j["meshes"][0]["primitives"][0], second = first;
  first["indices"] = h.add_accessor(std::vector<uint16_t>(indices.begin(), indices.begin() + 18), 5123, "SCALAR", 18);
  second["indices"] = h.add_accessor(std::vector<uint16_t>(indices.begin() + 18, indices.end()), 5123, "SCALAR", 18);
  h.j["meshes"][0]["primitives"] = {first, second};
  const CovarianceMesh m = read_mesh(dir.write("cube.glb", h.glb()));
  test::expect_closed_outward(m, 8, 12);
  EXPECT_NEAR(test::signed_volume(m), 8.0, 1e-12);
}

}  // namespace
}  // namespace gps
