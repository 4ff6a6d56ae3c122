// glTF files as other tools and hands write them, read as the docs promise: buffer files from the
// .gltf's folder only, by their uri's own decoding; images that cannot be read passed with one note;
// attributes gpsurf drops noted; meshes in the scene's order; counts no buffer holds, other versions
// and malformed .glb chunks refused in one line of gpsurf's words.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>

#include "core/io/gltf_head.h"
#include "core/io/mesh_io.h"
#include "core/support/error.h"
#include "tests/support/error_of.h"
#include "tests/support/hand_made_gltf.h"
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
  cube.j["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = 0;  // any accessor: it is not read
  cube.j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 0;
  cube.j["meshes"][0]["primitives"][0]["attributes"]["_BATCHID"] = 0;
  const std::vector<std::string> notes = notes_of(dir.write("attributes.glb", cube.glb()));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("24 texture coordinates, 24 vertex colours and vertex attribute '_BATCHID' dropped"),
            std::string::npos)
      << notes[0];
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
            ": has a buffer without a uri (only a .glb's first buffer may go without: it is the BIN chunk)");
  json too_long = cube.j;
  too_long["buffers"] = json::array({{{"byteLength", cube.bin.size() - 16}, {"uri", "long.bin"}}});
  dir.write("long.bin", cube.bin);
  EXPECT_EQ(refusal("long.gltf", too_long.dump()),
            ": names a buffer file 'long.bin' of " + std::to_string(cube.bin.size()) +
                " bytes where its byteLength is " + std::to_string(cube.bin.size() - 16));
}

}  // namespace
}  // namespace gps
