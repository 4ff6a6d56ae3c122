#pragma once
// glTF files made by hand in the tests: a buffer of float positions and u16 indices, and the JSON
// naming them, written as a .glb or as a .gltf with its .bin.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"

namespace gps::test {

// A hand-made file: a buffer of float positions and u16 indices, and the JSON naming them.
struct HandMade {
  std::string bin;
  nlohmann::json j;

  template <class T>
  void append(const std::vector<T>& values) {
    bin.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
    while (bin.size() % 4) bin.push_back('\0');
  }

  // `values` in a buffer view of their own and an accessor of `count` elements of `type` ("VEC2") and
  // `component_type` (5126 float, 5121 unsigned byte …) over it; its index.
  template <class T>
  size_t add_accessor(const std::vector<T>& values, int component_type, const std::string& type, size_t count) {
    const size_t offset = bin.size();
    append(values);
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}});
    j["accessors"].push_back({{"bufferView", j["bufferViews"].size() - 1},
                              {"componentType", component_type},
                              {"count", count},
                              {"type", type}});
    return j["accessors"].size() - 1;
  }

  // Per vertex of the first primitive its Σ (column-major floats), as the _COVARIANCE attribute.
  void add_covariances(const std::vector<Mat3>& sigmas) {
    std::vector<float> covariances;
    for (const Mat3& sigma : sigmas)
      for (int k = 0; k < 9; ++k) covariances.push_back(float(sigma(k % 3, k / 3)));
    j["meshes"][0]["primitives"][0]["attributes"]["_COVARIANCE"] =
        add_accessor(covariances, 5126, "MAT3", sigmas.size());
  }

  // The .glb of it: header, JSON chunk (padded with spaces), BIN chunk (padded with zeros). The BIN chunk and
  // the buffer may claim `overclaimed` bytes more than the chunk holds.
  std::string glb(uint32_t overclaimed = 0) const {
    nlohmann::json with_buffer = j;
    with_buffer["buffers"] = nlohmann::json::array({{{"byteLength", bin.size() + overclaimed}}});
    std::string text = with_buffer.dump();
    while (text.size() % 4) text.push_back(' ');
    std::string out = "glTF";
    const auto word = [&](uint32_t w) { out.append(reinterpret_cast<const char*>(&w), 4); };
    word(2);
    word(uint32_t(12 + 8 + text.size() + 8 + bin.size()));
    word(uint32_t(text.size()));
    out += "JSON" + text;
    word(uint32_t(bin.size() + overclaimed));
    out += std::string("BIN\0", 4) + bin;
    return out;
  }

  // The .gltf of it, its buffer in `bin_name` beside it.
  void write_gltf(const TempDir& dir, const std::string& name, const std::string& bin_name) const {
    nlohmann::json with_buffer = j;
    with_buffer["buffers"] = nlohmann::json::array({{{"byteLength", bin.size()}, {"uri", bin_name}}});
    dir.write(bin_name, bin);
    dir.write(name, with_buffer.dump(1));
  }
};

// A cube as glTF exporters write it: each face its own 4 vertices (split at the normal seams), 24 in all.
inline HandMade split_cube() {
  HandMade h;
  std::vector<float> positions;
  std::vector<uint16_t> indices;
  const int axes[3][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}};
  for (const auto& a : axes)
    for (const float side : {-1.0f, 1.0f}) {
      const uint16_t first = uint16_t(positions.size() / 3);
      const float square[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& s : square) {
        float p[3];
        p[a[0]] = side;
        p[a[1]] = s[0];
        p[a[2]] = s[1];
        positions.insert(positions.end(), p, p + 3);
      }
      // Counter-clockwise seen from outside: (u, v, n) is right-handed for each axis triple above.
      if (side > 0)
        indices.insert(indices.end(), {first, uint16_t(first + 1), uint16_t(first + 2), first, uint16_t(first + 2),
                                       uint16_t(first + 3)});
      else
        indices.insert(indices.end(), {first, uint16_t(first + 2), uint16_t(first + 1), first, uint16_t(first + 3),
                                       uint16_t(first + 2)});
    }
  h.append(positions);
  const size_t index_offset = h.bin.size();
  h.append(indices);
  h.j = {{"asset", {{"version", "2.0"}}},
         {"bufferViews",
          {{{"buffer", 0}, {"byteLength", positions.size() * 4}, {"target", 34962}},
           {{"buffer", 0}, {"byteOffset", index_offset}, {"byteLength", indices.size() * 2}, {"target", 34963}}}},
         {"accessors",
          {{{"bufferView", 0},
            {"componentType", 5126},
            {"count", 24},
            {"type", "VEC3"},
            {"min", {-1, -1, -1}},
            {"max", {1, 1, 1}}},
           {{"bufferView", 1}, {"componentType", 5123}, {"count", 36}, {"type", "SCALAR"}}}},
         {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}, {"mode", 4}}}}}}},
         {"nodes", {{{"mesh", 0}}}},
         {"scenes", {{{"nodes", {0}}}}},
         {"scene", 0}};
  return h;
}

}  // namespace gps::test
