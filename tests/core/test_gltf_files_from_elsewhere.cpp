// glTF files as other tools and hands write them, read as the docs promise: buffer files from the
// .gltf's folder only, by their uri's own decoding; images that cannot be read passed with one note;
// attributes and primitives gpsurf drops noted, and checked as glTF defines them; meshes in the scene's
// order; morph targets applied by the default weights; counts no buffer holds, other versions,
// primitives, accessors and morph targets glTF has not and malformed .glb chunks refused in one line of
// gpsurf's words.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <vector>

#include "core/io/gltf_head.h"
#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "tests/support/error_of.h"
#include "tests/support/hand_made_gltf.h"
#include "tests/support/mesh_checks.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

using nlohmann::json;

// The cube's .gltf with its buffer's uri `uri`, the .bin written as `file` (both in `dir`).
std::string gltf_naming(const test::TempDir& dir, const std::string& name, const std::string& uri,
                        const std::string& file) {
  const test::HandMade cube = test::split_cube();
  json j = cube.j;
  j["buffers"] = json::array({{{"byteLength", cube.bin.size()}, {"uri", uri}}});
  dir.write(file, cube.bin);
  return dir.write(name, j.dump());
}

std::vector<std::string> notes_of(const std::string& path) {
  std::vector<std::string> notes;
  read_mesh(path, {}, nullptr, &notes);
  return notes;
}

TEST(GltfFilesFromElsewhere, BufferFilesAreReadFromTheGltfsFolderOnlyByTheirUrisDecoding) {
  test::TempDir dir;
  std::filesystem::create_directory(dir.file("sub"));
  // The buffer lies in the working folder, not beside the .gltf: refused wherever the command runs.
  gltf_naming(dir, "sub/x.gltf", "only.bin", "only.bin");
  std::filesystem::remove(dir.file("sub/only.bin"));
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir.file(""));
  const std::string refused = test::error_of([] { read_mesh("sub/x.gltf"); });
  std::filesystem::current_path(before);
  EXPECT_NE(refused.find("names a buffer file 'only.bin' that is not there"), std::string::npos) << refused;

  // '+' is a plus in a uri's path, %20 a space (RFC 3986), whatever a form's decoding says.
  EXPECT_EQ(read_mesh(gltf_naming(dir, "plus.gltf", "mesh+v2.bin", "mesh+v2.bin")).n_vertices(), 8u);
  EXPECT_EQ(read_mesh(gltf_naming(dir, "space.gltf", "my%20cube+1.bin", "my cube+1.bin")).n_vertices(), 8u);
  EXPECT_EQ(uri_decoded("a%2Bb+c%20d%zz%4"), "a+b+c d%zz%4");
  EXPECT_EQ(uri_form_decoded("a%2Bb+c%20d"), "a+b c d");
}

TEST(GltfFilesFromElsewhere, ImagesThatCannotBeReadAreReadPastWithOneNote) {
  test::TempDir dir;
  test::HandMade cube = test::split_cube();
  cube.j["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
  cube.j["meshes"][0]["primitives"][0]["material"] = 0;
  cube.j["textures"] = {{{"source", 0}}};
  // Embedded data that is not base64: the mesh is read all the same.
  cube.j["images"] = {{{"uri", "data:image/png;base64,@@@@"}}};
  for (const char* name : {"undecodable.glb", "undecodable.gltf"}) {
    const std::string path = std::string(name).ends_with(".glb") ? dir.write(name, cube.glb()) : dir.file(name);
    if (!std::string(name).ends_with(".glb")) cube.write_gltf(dir, name, "undecodable.bin");
    EXPECT_EQ(read_mesh(path).n_faces(), 12u) << name;
    const std::vector<std::string> notes = notes_of(path);
    ASSERT_EQ(notes.size(), 1u) << name;
    EXPECT_NE(notes[0].find("its images could not be decoded and were read past"), std::string::npos) << notes[0];
  }
  // A missing image file, its name holding a line break: one note, on one line, no name of the file's shown.
  cube.j["images"] = {{{"uri", "tex.png\ngpsurf: forged line"}}};
  const std::string path = dir.write("newline.glb", cube.glb());
  const std::vector<std::string> notes = notes_of(path);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("1 image is not there or empty, read past"), std::string::npos) << notes[0];
  EXPECT_EQ(notes[0].find('\n'), std::string::npos);
  EXPECT_EQ(notes[0].find("forged line"), std::string::npos);
}

TEST(GltfFilesFromElsewhere, AttributesThatAreDroppedAreNoted) {
  test::TempDir dir;
  test::HandMade cube = test::split_cube();
  json& attributes = cube.j["meshes"][0]["primitives"][0]["attributes"];
  attributes["TEXCOORD_0"] = cube.add_accessor(std::vector<float>(48, 0.5f), 5126, "VEC2", 24);
  attributes["COLOR_0"] = 0;  // the positions, VEC3 float: colours as glTF allows them
  attributes["_BATCHID"] = 0;
  const std::vector<std::string> notes = notes_of(dir.write("attributes.glb", cube.glb()));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("24 texture coordinates, 24 vertex colours and vertex attribute '_BATCHID' dropped"),
            std::string::npos)
      << notes[0];
  // Every set is counted, not only the first (TEXCOORD_1 and COLOR_1 alone were dropped without a word).
  attributes["TEXCOORD_1"] = attributes["TEXCOORD_0"];
  attributes["COLOR_1"] = attributes["COLOR_0"];
  attributes.erase("_BATCHID");
  EXPECT_NE(notes_of(dir.write("sets.glb", cube.glb())).at(0).find("48 texture coordinates and 48 vertex colours"),
            std::string::npos);
  attributes.erase("TEXCOORD_0");
  attributes.erase("COLOR_0");
  EXPECT_NE(notes_of(dir.write("second.glb", cube.glb())).at(0).find("24 texture coordinates and 24 vertex colours"),
            std::string::npos);
}

// A primitive of lines or points beside the triangles: the note says it is dropped, as an OBJ's `l`.
TEST(GltfFilesFromElsewhere, PrimitivesWithoutTrianglesAreNoted) {
  test::TempDir dir;
  test::HandMade cube = test::split_cube();
  json& primitives = cube.j["meshes"][0]["primitives"];
  const json triangles = primitives[0];
  for (const int mode : {1, 1, 3, 0}) {
    primitives.push_back(triangles);
    primitives.back()["mode"] = mode;
  }
  const std::string path = dir.write("lines.glb", cube.glb());
  EXPECT_EQ(read_mesh(path).n_faces(), 12u);
  EXPECT_EQ(notes_of(path), (std::vector<std::string>{path + ": 1 POINTS primitive, 2 LINES primitives and 1 "
                                                             "LINE_STRIP primitive dropped (a covariance mesh keeps "
                                                             "positions, Gaussians and creases; normals come from the "
                                                             "limit surface)"}));
}

// The one-line refusal of the file, without its path, checked to be one line that begins with it.
std::string refusal_of(const test::TempDir& dir, const std::string& name, const std::string& contents) {
  const std::string path = dir.write(name, contents);
  const std::string why = test::error_of([&] { read_mesh(path); });
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
  EXPECT_EQ(why.rfind(path + ": ", 0), 0u) << why;
  return why.substr(std::min(why.size(), path.size() + 2));
}

// tinygltf dropped a primitive whose attributes it could not read (its triangles lost, exit 0) and
// read a mode glTF has not as no triangles: refused, naming the mesh and the primitive.
TEST(GltfFilesFromElsewhere, APrimitiveGltfHasNotIsRefusedNamingIt) {
  test::TempDir dir;
  for (const bool alone : {false, true}) {
    test::HandMade cube = test::split_cube();
    json& primitives = cube.j["meshes"][0]["primitives"];
    if (!alone) primitives.push_back(primitives[0]);
    json& bad = primitives.back();
    const std::string where = alone ? "mesh 0 primitive 0" : "mesh 0 primitive 1";
    const auto refused = [&] { return refusal_of(dir, "bad.glb", cube.glb()); };
    bad["attributes"]["TEXCOORD_0"] = "x";
    EXPECT_EQ(refused(), where + ": attribute 'TEXCOORD_0' is 'x', not an accessor's index");
    bad["attributes"]["TEXCOORD_0"] = 1.5;
    EXPECT_EQ(refused(), where + ": attribute 'TEXCOORD_0' is 1.5, not an accessor's index");
    bad["attributes"]["TEXCOORD_0"] = nullptr;
    EXPECT_EQ(refused(), where + ": attribute 'TEXCOORD_0' is a null, not an accessor's index");
    bad["attributes"]["TEXCOORD_0"] = 99;
    EXPECT_EQ(refused(), where + ": attribute 'TEXCOORD_0' names accessor 99, which is not in the file");
    bad["attributes"].erase("TEXCOORD_0");
    bad["indices"] = "1";
    EXPECT_EQ(refused(), where + ": indices is '1', not an accessor's index");
    bad["indices"] = 1;
    bad["mode"] = 7;
    EXPECT_EQ(refused(), where + ": mode 7 is none of glTF's (0 POINTS to 6 TRIANGLE_FAN)");
    bad["mode"] = "4";
    EXPECT_EQ(refused(), where + ": mode '4' is none of glTF's (0 POINTS to 6 TRIANGLE_FAN)");
    bad.erase("mode");
    bad.erase("attributes");
    EXPECT_EQ(refused(), where + " has no attributes");
  }
}

// Texture coordinates and colours are dropped, but read as glTF defines them: each accessor one of
// the types glTF allows for its attribute, in its buffer, one element per position.
TEST(GltfFilesFromElsewhere, DroppedAttributesAreCheckedAsGltfDefinesThem) {
  test::TempDir dir;
  const auto with = [](const std::string& attribute, auto values, int component_type, const std::string& type,
                       size_t count) {
    test::HandMade cube = test::split_cube();
    cube.j["meshes"][0]["primitives"][0]["attributes"][attribute] =
        cube.add_accessor(values, component_type, type, count);
    return cube;
  };
  const std::vector<float> uv(48, 0.5f);
  const auto refused = [&](const test::HandMade& h) { return refusal_of(dir, "uv.glb", h.glb()); };
  const std::string uv_accessor = "mesh 0 primitive 0: TEXCOORD_0 accessor 2 ";
  EXPECT_EQ(refused(with("TEXCOORD_0", std::vector<float>(72), 5126, "VEC3", 24)), uv_accessor + "is VEC3, not VEC2");
  EXPECT_EQ(refused(with("TEXCOORD_0", uv, 5126, "VEC2", 2)), uv_accessor + "has 2 elements for 24 positions");
  EXPECT_EQ(refused(with("TEXCOORD_0", std::vector<uint32_t>(48), 5125, "VEC2", 24)),
            uv_accessor + "has UNSIGNED_INT components, not FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT");
  EXPECT_EQ(refused(with("TEXCOORD_0", std::vector<uint8_t>(48), 5121, "VEC2", 24)),
            uv_accessor + "has UNSIGNED_BYTE components that are not normalized (TEXCOORD_0's integers must be)");
  EXPECT_EQ(refused(with("TEXCOORD_0", uv, 5126, "VEC2", 0)),
            "accessor 2: count 0 is not a count of elements (1 or more)");
  test::HandMade no_view = with("TEXCOORD_0", uv, 5126, "VEC2", 24);
  no_view.j["accessors"][2]["bufferView"] = 99;
  EXPECT_EQ(refused(no_view), uv_accessor + "has no buffer view in the file");
  test::HandMade short_view = with("TEXCOORD_0", uv, 5126, "VEC2", 24);
  short_view.j["bufferViews"][2]["byteLength"] = 100;
  EXPECT_EQ(refused(short_view), uv_accessor + "reads past its buffer view");
  test::HandMade misaligned = with("TEXCOORD_0", std::vector<float>(50), 5126, "VEC2", 24);
  misaligned.j["accessors"][2]["byteOffset"] = 2;
  EXPECT_EQ(refused(misaligned),
            uv_accessor + "starts at byte 362 of its buffer, not a multiple of its components' 4 bytes");
  const std::string colour_accessor = "mesh 0 primitive 0: COLOR_0 accessor 2 ";
  EXPECT_EQ(refused(with("COLOR_0", uv, 5126, "VEC2", 24)), colour_accessor + "is VEC2, not VEC3 or VEC4");
  EXPECT_EQ(refused(with("COLOR_0", std::vector<float>(384), 5126, "MAT4", 24)),
            colour_accessor + "is MAT4, not VEC3 or VEC4");
  EXPECT_EQ(refused(with("COLOR_0", std::vector<int8_t>(96), 5120, "VEC4", 24)),
            colour_accessor + "has BYTE components, not FLOAT, UNSIGNED_BYTE or UNSIGNED_SHORT");

  // What glTF allows reads: normalized integers; no buffer view (zeros); with KHR_mesh_quantization,
  // integer texture coordinates that are not normalized.
  test::HandMade bytes = with("TEXCOORD_0", std::vector<uint8_t>(48), 5121, "VEC2", 24);
  bytes.j["accessors"][2]["normalized"] = true;
  test::HandMade colours = with("COLOR_0", std::vector<uint16_t>(96), 5123, "VEC4", 24);
  colours.j["accessors"][2]["normalized"] = true;
  test::HandMade zeros = with("TEXCOORD_0", uv, 5126, "VEC2", 24);
  zeros.j["accessors"][2].erase("bufferView");
  test::HandMade quantized = with("TEXCOORD_0", std::vector<int16_t>(48), 5122, "VEC2", 24);
  quantized.j["extensionsUsed"] = {"KHR_mesh_quantization"};
  for (const test::HandMade* h : {&bytes, &colours, &zeros, &quantized})
    EXPECT_EQ(read_mesh(dir.write("fine.glb", h->glb())).n_vertices(), 8u);
  EXPECT_NE(refused(with("TEXCOORD_0", std::vector<int16_t>(48), 5122, "VEC2", 24)).find("has SHORT components"),
            std::string::npos);
}

// tinygltf's words for an accessor glTF has not, for a JSON chunk that is not padded (glued to the
// next message) and for a .glb without the BIN chunk its buffer needs: gpsurf's words, one reason.
TEST(GltfFilesFromElsewhere, AccessorsAndChunksGltfHasNotAreRefusedInGpsurfsWords) {
  test::TempDir dir;
  test::HandMade cube = test::split_cube();
  cube.j["accessors"][1]["componentType"] = 9999;
  EXPECT_EQ(refusal_of(dir, "ct.glb", cube.glb()),
            "accessor 1: componentType 9999 is none of glTF's (5120, 5121, 5122, 5123, 5125 and 5126)");
  // The JSON chunk ending off a 4-byte boundary, the BIN chunk right after it.
  std::string glb = cube.glb();
  uint32_t json_length;
  std::memcpy(&json_length, glb.data() + 12, 4);
  std::string text = glb.substr(20, json_length), bin_chunk = glb.substr(20 + json_length);
  while (text.back() == ' ') text.pop_back();
  if (text.size() % 4 == 0) text += ' ';
  std::string unpadded = glb.substr(0, 20);
  const uint32_t unpadded_length = uint32_t(text.size()), total = uint32_t(20 + text.size() + bin_chunk.size());
  std::memcpy(unpadded.data() + 12, &unpadded_length, 4);
  std::memcpy(unpadded.data() + 8, &total, 4);
  unpadded += text + bin_chunk;
  EXPECT_EQ(refusal_of(dir, "unpadded.glb", unpadded),
            "accessor 1: componentType 9999 is none of glTF's (5120, 5121, 5122, 5123, 5125 and 5126)");
  cube.j["accessors"][1]["componentType"] = 5123;
  cube.j["accessors"][1]["type"] = "VEC7";
  EXPECT_EQ(refusal_of(dir, "type.glb", cube.glb()),
            "accessor 1: type 'VEC7' is none of glTF's (SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 and MAT4)");
  cube.j["accessors"][1].erase("type");
  EXPECT_EQ(refusal_of(dir, "no_type.glb", cube.glb()), "accessor 1 has no type");

  // A .glb whose buffer has no uri and no BIN chunk to hold it.
  const test::HandMade fine = test::split_cube();
  std::string no_bin = fine.glb();
  std::memcpy(&json_length, no_bin.data() + 12, 4);
  no_bin.resize(20 + json_length);
  const uint32_t length = uint32_t(no_bin.size());
  std::memcpy(no_bin.data() + 8, &length, 4);
  EXPECT_EQ(refusal_of(dir, "no_bin.glb", no_bin), "buffer 0 has no uri, and the .glb no BIN chunk to hold it");
}

TEST(GltfFilesFromElsewhere, MeshesComeInTheScenesOrder) {
  test::TempDir dir;
  test::HandMade two = test::split_cube();
  two.j["nodes"] = {{{"mesh", 0}, {"translation", {10, 0, 0}}, {"children", {1, 2}}},
                    {{"mesh", 0}, {"translation", {10, 0, 0}}},
                    {{"mesh", 0}, {"translation", {20, 0, 0}}}};
  const CovarianceMesh m = read_mesh(dir.write("order.glb", two.glb()));
  ASSERT_EQ(m.n_vertices(), 24u);
  // The root first (x about 10), then its children in order (20, then 30).
  EXPECT_NEAR(m.mean(0).x(), 10, 1.5);
  EXPECT_NEAR(m.mean(8).x(), 20, 1.5);
  EXPECT_NEAR(m.mean(16).x(), 30, 1.5);
}

TEST(GltfFilesFromElsewhere, WhatNoReaderCouldReadIsRefusedInGpsurfsWords) {
  test::TempDir dir;
  const test::HandMade cube = test::split_cube();
  const auto refusal = [&](const std::string& name, const std::string& contents) {
    const std::string path = dir.write(name, contents);
    const std::string why = test::error_of([&] { read_mesh(path); });
    EXPECT_EQ(why.find('\n'), std::string::npos) << why;
    EXPECT_EQ(why.rfind(path, 0), 0u) << why;
    return why.substr(path.size());
  };
  // A count that no buffer holds: the accessor is named, not the memory it would take.
  test::HandMade huge = cube;
  huge.j["accessors"][0]["count"] = 1000000000;
  EXPECT_EQ(refusal("huge.glb", huge.glb()), ": mesh 0 primitive 0: POSITION accessor 0 reads past its buffer view");
  test::HandMade version_1 = cube;
  version_1.j["asset"]["version"] = "1.0";
  EXPECT_EQ(refusal("one.glb", version_1.glb()),
            ": is glTF '1.0'; gpsurf reads glTF 2.0 (convert the file, e.g. with Blender)");

  const std::string glb = cube.glb();
  uint32_t json_length;
  std::memcpy(&json_length, glb.data() + 12, 4);
  std::string not_json = glb;
  not_json.replace(16, 4, "XXXX");
  EXPECT_EQ(refusal("type.glb", not_json),
            ": is a .glb whose first chunk is not its JSON (its type is 0x58585858, JSON's 0x4E4F534A)");
  std::string not_bin = glb;
  not_bin.replace(20 + json_length + 4, 4, "XXXX");
  EXPECT_EQ(refusal("bin.glb", not_bin),
            ": is a .glb whose second chunk is not BIN (its type is 0x58585858, BIN's 0x004E4942)");
  // An empty BIN chunk after the JSON, the buffer external.
  std::string empty_bin = glb.substr(0, 20 + json_length) + std::string(4, '\0') + std::string("BIN\0", 4);
  const uint32_t total = uint32_t(empty_bin.size());
  std::memcpy(empty_bin.data() + 8, &total, 4);
  EXPECT_NE(refusal("empty.glb", empty_bin).find("whose BIN chunk holds 0 bytes"), std::string::npos);

  json no_uri = cube.j;
  no_uri["buffers"] = json::array({{{"byteLength", 8}}});
  EXPECT_EQ(refusal("no_uri.gltf", no_uri.dump()),
            ": buffer 0 has no uri (only a .glb's buffer may go without: its BIN chunk)");
  json too_long = cube.j;
  too_long["buffers"] = json::array({{{"byteLength", cube.bin.size() - 16}, {"uri", "long.bin"}}});
  dir.write("long.bin", cube.bin);
  EXPECT_EQ(refusal("long.gltf", too_long.dump()),
            ": names a buffer file 'long.bin' of " + std::to_string(cube.bin.size()) +
                " bytes where its byteLength is " + std::to_string(cube.bin.size() - 16));
}

}  // namespace
}  // namespace gps

namespace gps {
namespace {

// The split cube with two morph targets, as Blender writes shape keys: target 0 moves its +x side by
// (1, 0, 0), target 1 its +y side by (0, 2, 0); the mesh's default weights `weights`.
test::HandMade morphing_cube(const json& weights) {
  test::HandMade h = test::split_cube();
  std::vector<float> positions(72), right(72, 0.0f), up(72, 0.0f);
  std::memcpy(positions.data(), h.bin.data(), 72 * sizeof(float));
  for (size_t v = 0; v < 24; ++v) {
    if (positions[3 * v] > 0) right[3 * v] = 1;
    if (positions[3 * v + 1] > 0) up[3 * v + 1] = 2;
  }
  h.j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", h.add_accessor(right, 5126, "VEC3", 24)}},
                                                  {{"POSITION", h.add_accessor(up, 5126, "VEC3", 24)}}};
  if (!weights.is_null()) h.j["meshes"][0]["weights"] = weights;
  return h;
}

// The cube's corners as read, sorted: the morph moves its sides, the weld still makes 8 of the 24.
std::vector<std::array<double, 3>> corners_of(const CovarianceMesh& m) {
  std::vector<std::array<double, 3>> corners;
  for (size_t v = 0; v < m.n_vertices(); ++v) corners.push_back({m.mean(v).x(), m.mean(v).y(), m.mean(v).z()});
  std::sort(corners.begin(), corners.end());
  return corners;
}

// The corners of the box [−1, right] × [−1, up] × [−1, 1], scaled by `scale`.
std::vector<std::array<double, 3>> box(double right, double up, double scale = 1) {
  std::vector<std::array<double, 3>> corners;
  for (const double x : {-1.0, right})
    for (const double y : {-1.0, up})
      for (const double z : {-1.0, 1.0}) corners.push_back({scale * x, scale * y, scale * z});
  std::sort(corners.begin(), corners.end());
  return corners;
}

// A viewer shows a mesh morphed by its default weights (the node's where it gives them, else the
// mesh's): read so, its targets' POSITION sparse or not, and all-zero weights give the base as it is.
TEST(GltfFilesFromElsewhere, MorphTargetsMoveThePositionsByTheDefaultWeights) {
  test::TempDir dir;
  const auto read = [&](const test::HandMade& h, const std::string& name) {
    const CovarianceMesh m = read_mesh(dir.write(name, h.glb()));
    EXPECT_EQ(test::shape_of(m).boundary_edges, 0) << name;
    return corners_of(m);
  };
  const test::HandMade mesh_weights = morphing_cube(json::array({0.5, 0.25}));
  EXPECT_EQ(read(mesh_weights, "mesh.glb"), box(1.5, 1.5));
  mesh_weights.write_gltf(dir, "mesh.gltf", "mesh.bin");
  EXPECT_EQ(corners_of(read_mesh(dir.file("mesh.gltf"))), box(1.5, 1.5));
  // The node's weights override the mesh's; the morph comes before the node's transform.
  test::HandMade node_weights = mesh_weights;
  node_weights.j["nodes"][0] = {{"mesh", 0}, {"weights", {1, 0}}, {"scale", {2, 2, 2}}};
  EXPECT_EQ(read(node_weights, "node.glb"), box(2, 1, 2));

  // Target 0 sparse, as Blender writes a shape key that moves few vertices: no buffer view (zeros),
  // the 12 moved positions' indices and displacements.
  test::HandMade sparse = mesh_weights;
  std::vector<float> positions(72), displacements;
  std::memcpy(positions.data(), sparse.bin.data(), 72 * sizeof(float));
  std::vector<uint16_t> moved;
  for (uint16_t v = 0; v < 24; ++v)
    if (positions[3 * v] > 0) {
      moved.push_back(v);
      displacements.insert(displacements.end(), {1, 0, 0});
    }
  const size_t position = sparse.j["meshes"][0]["primitives"][0]["targets"][0]["POSITION"].get<size_t>();
  sparse.j["accessors"][position].erase("bufferView");
  const size_t indices = sparse.add_accessor(moved, 5123, "SCALAR", moved.size());
  const size_t values = sparse.add_accessor(displacements, 5126, "VEC3", moved.size());
  // Taken after the accessors are added: adding them may move the array's elements.
  json& target = sparse.j["accessors"][position];
  target["sparse"] = {
      {"count", moved.size()},
      {"indices", {{"bufferView", sparse.j["accessors"][indices]["bufferView"]}, {"componentType", 5123}}},
      {"values", {{"bufferView", sparse.j["accessors"][values]["bufferView"]}}}};
  EXPECT_EQ(read(sparse, "sparse.glb"), box(1.5, 1.5));
  // With KHR_mesh_quantization, a target of normalized shorts (32767 is 1).
  test::HandMade quantized = mesh_weights;
  std::vector<int16_t> shorts(72, 0);
  for (const uint16_t v : moved) shorts[3 * v] = 32767;
  const size_t right = quantized.add_accessor(shorts, 5122, "VEC3", 24);
  quantized.j["accessors"][right]["normalized"] = true;
  quantized.j["meshes"][0]["primitives"][0]["targets"][0]["POSITION"] = right;
  quantized.j["extensionsUsed"] = {"KHR_mesh_quantization"};
  EXPECT_EQ(read(quantized, "quantized.glb"), box(1.5, 1.5));

  // All-zero weights, no weights, or targets of normals only: the base, bit for bit.
  const CovarianceMesh base = read_mesh(dir.write("base.glb", test::split_cube().glb()));
  test::HandMade normals = morphing_cube(json::array({1}));
  normals.j["meshes"][0]["primitives"][0]["targets"] = {{{"NORMAL", 2}}};
  for (const auto& [name, h] : {std::pair{"zero.glb", morphing_cube(json::array({0, 0}))},
                                {"none.glb", morphing_cube(json())},
                                {"normals.glb", normals}})
    EXPECT_TRUE(test::same_mesh(read_mesh(dir.write(name, h.glb())), base)) << name;
}

// Targets and weights are read as glTF 2.0 defines them (§3.7.2.2): a POSITION displacement per position,
// VEC3 float, weights as many as the targets, numbers; refused in one line naming the element.
TEST(GltfFilesFromElsewhere, MorphTargetsGltfHasNotAreRefusedNamingThem) {
  test::TempDir dir;
  const auto refused = [&](const test::HandMade& h) { return refusal_of(dir, "morph.glb", h.glb()); };
  test::HandMade few = morphing_cube(json::array({0.5, 0.5}));
  few.j["accessors"][2]["count"] = 4;
  EXPECT_EQ(refused(few), "mesh 0 primitive 0: target 0 POSITION accessor 2 has 4 elements for 24 positions");
  test::HandMade flat = morphing_cube(json::array({0.5, 0.5}));
  flat.j["accessors"][3]["type"] = "VEC2";
  flat.j["accessors"][3]["count"] = 24;
  EXPECT_EQ(refused(flat), "mesh 0 primitive 0: target 1 POSITION accessor 3 is VEC2, not VEC3");
  test::HandMade shorts = morphing_cube(json::array({0.5, 0.5}));
  shorts.j["accessors"][3]["componentType"] = 5123;
  EXPECT_EQ(refused(shorts),
            "mesh 0 primitive 0: target 1 POSITION accessor 3 has UNSIGNED_SHORT components, not FLOAT");
  test::HandMade weights = morphing_cube(json::array({0.5, 0.5}));
  weights.j["nodes"][0]["weights"] = {1, 0, 0};
  EXPECT_EQ(refused(weights), "mesh 0 primitive 0: 2 morph targets for the 3 weights of node 0");
  weights.j["nodes"][0]["weights"] = {1, "0"};
  EXPECT_EQ(refused(weights), "node 0: weight 1 is '0', not a number");
  weights.j["nodes"][0].erase("weights");
  weights.j["meshes"][0]["weights"] = 0.5;
  EXPECT_EQ(refused(weights), "mesh 0: weights is 0.5, not an array");
  test::HandMade missing = morphing_cube(json::array({0.5, 0.5}));
  missing.j["meshes"][0]["primitives"][0]["targets"][1]["POSITION"] = 9;
  EXPECT_EQ(refused(missing),
            "mesh 0 primitive 0: target 1 attribute 'POSITION' names accessor 9, which is not in the file");
  missing.j["meshes"][0]["primitives"][0]["targets"][1] = 3;
  EXPECT_EQ(refused(missing), "mesh 0 primitive 0 target 1 is 3, not an object");
  // A sparse index past the positions.
  test::HandMade past = morphing_cube(json::array({0.5, 0.5}));
  const size_t index = past.add_accessor(std::vector<uint16_t>{30}, 5123, "SCALAR", 1);
  const size_t value = past.add_accessor(std::vector<float>{1, 0, 0}, 5126, "VEC3", 1);
  past.j["accessors"][2]["sparse"] = {
      {"count", 1},
      {"indices", {{"bufferView", past.j["accessors"][index]["bufferView"]}, {"componentType", 5123}}},
      {"values", {{"bufferView", past.j["accessors"][value]["bufferView"]}}}};
  EXPECT_EQ(refused(past),
            "mesh 0 primitive 0: target 0 POSITION accessor 2 sparse index 0 is 30, past its 24 elements");
}

}  // namespace
}  // namespace gps
