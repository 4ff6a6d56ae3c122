#include "core/io/gltf_io.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <span>
#include <unordered_map>

#include <Eigen/Geometry>
#include <tiny_gltf.h>

#include "core/io/dropped_attributes.h"
#include "core/io/face_triangulation.h"
#include "core/io/gltf_loading.h"
#include "core/io/text_file.h"
#include "core/support/error.h"
#include "core/support/memory_budget.h"
#include "core/support/quoted_text.h"

namespace gps {

namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
constexpr const char* kCovarianceAttribute = "_COVARIANCE";
// The asset generator gpsurf writes, by which it knows its own files (their vertices are not welded).
const std::string kGenerator = "gpsurf";

// An accessor's elements as bytes in its buffer: `count` elements `stride` bytes apart (no data where
// its values are not read and it has none in a buffer: a sparse accessor, or one of zeros).
struct AccessorBytes {
  const unsigned char* data = nullptr;
  size_t count = 0, stride = 0;
  int component_type = 0;
  bool normalized = false;
};

// What an attribute's accessor may be (glTF 2.0 §3.7.2.1, and KHR_mesh_quantization's widening).
struct AccessorRule {
  std::vector<int> types, component_types;
  bool integers_normalized = false;  // integer components must be normalized (mapped to [0, 1] or [−1, 1])
  // false: an accessor that may be sparse or all zeros (no buffer view): an attribute dropped unread, or
  // one read by vec3_values
  bool values_read = true;
};

// A type's name (tinygltf numbers SCALAR 65, VECn n and MATn 32 + n).
std::string type_name(int type) {
  return type == TINYGLTF_TYPE_SCALAR ? "SCALAR" : (type & 32 ? "MAT" : "VEC") + std::to_string(type & 31);
}

// A componentType's name (read_gltf_head has checked it is one of glTF's, which 5124, INT, is not).
std::string component_type_name(int component_type) {
  constexpr std::array<const char*, 6> kNames = {"BYTE",           "UNSIGNED_BYTE", "SHORT",
                                                 "UNSIGNED_SHORT", "INT",           "UNSIGNED_INT"};
  return component_type >= 5120 && component_type <= 5125 ? kNames[size_t(component_type - 5120)] : "FLOAT";
}

// "A", "A or B", "A, B or C", each value named by `name`.
std::string one_of(const std::vector<int>& values, std::string (*name)(int)) {
  std::string out;
  for (size_t k = 0; k < values.size(); ++k)
    out += (k == 0 ? "" : k + 1 == values.size() ? " or " : ", ") + name(values[k]);
  return out;
}

// The bytes of accessor `a`'s elements, `name` naming it in messages: each element inside its buffer
// view, the view inside its buffer, and its start aligned to its component size (glTF 2.0 §3.6.2.4).
AccessorBytes bytes_in_view(const tinygltf::Model& model, const tinygltf::Accessor& a, const std::string& name) {
  AccessorBytes bytes{nullptr, a.count, 0, a.componentType, a.normalized};
  if (a.bufferView < 0 || size_t(a.bufferView) >= model.bufferViews.size())
    throw Error(name + " has no buffer view in the file");
  const tinygltf::BufferView& view = model.bufferViews[size_t(a.bufferView)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    throw Error(name + ": buffer view " + std::to_string(a.bufferView) + " has no buffer in the file");
  const std::vector<unsigned char>& buffer = model.buffers[size_t(view.buffer)].data;
  if (view.byteOffset > buffer.size() || view.byteLength > buffer.size() - view.byteOffset)
    throw Error(name + ": buffer view " + std::to_string(a.bufferView) + " reads past its buffer");
  const size_t component = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(a.componentType)));
  const size_t element = component * size_t(tinygltf::GetNumComponentsInType(uint32_t(a.type)));
  if ((view.byteOffset + a.byteOffset) % component != 0)
    throw Error(name + " starts at byte " + std::to_string(view.byteOffset + a.byteOffset) +
                " of its buffer, not a multiple of its components' " + std::to_string(component) + " bytes");
  bytes.stride = view.byteStride != 0 ? view.byteStride : element;
  if (bytes.stride < element)
    throw Error(name + ": its byte stride " + std::to_string(bytes.stride) + " is shorter than an element");
  // The last element ends at offset + stride (count − 1) + element, compared without overflow.
  const size_t room = view.byteLength;
  if (a.byteOffset > room || element > room - a.byteOffset ||
      (a.count - 1) > (room - a.byteOffset - element) / bytes.stride)
    throw Error(name + " reads past its buffer view");
  bytes.data = buffer.data() + view.byteOffset + a.byteOffset;
  return bytes;
}

// The bytes of accessor `index` (read_gltf_head has checked that it is in the file, and that its type
// and component type are glTF's), checked against `rule` and to lie in its buffer (bytes_in_view).
// `where` names the use ("mesh 0 primitive 1"), `what` the attribute.
AccessorBytes accessor_bytes(const tinygltf::Model& model, int index, const AccessorRule& rule,
                             const std::string& where, const std::string& what) {
  const std::string name = where + ": " + what + " accessor " + std::to_string(index);
  const tinygltf::Accessor& a = model.accessors.at(size_t(index));
  if (std::find(rule.types.begin(), rule.types.end(), a.type) == rule.types.end())
    throw Error(name + " is " + type_name(a.type) + ", not " + one_of(rule.types, type_name));
  const auto& components = rule.component_types;
  if (std::find(components.begin(), components.end(), a.componentType) == components.end())
    throw Error(name + " has " + component_type_name(a.componentType) + " components, not " +
                one_of(components, component_type_name));
  if (rule.integers_normalized && a.componentType != kFloat && !a.normalized)
    throw Error(name + " has " + component_type_name(a.componentType) + " components that are not normalized (" + what +
                "'s integers must be)");
  if (a.sparse.isSparse && rule.values_read) throw Error(name + " is sparse, which is not read");
  if (a.bufferView < 0 && !rule.values_read) return AccessorBytes{nullptr, a.count, 0, a.componentType, a.normalized};
  return bytes_in_view(model, a, name);
}

float float_at(const AccessorBytes& b, size_t i, int k) {
  float value;
  std::memcpy(&value, b.data + i * b.stride + size_t(k) * sizeof(float), sizeof value);
  return value;
}

// Component k of element i as a number: a float as it is, an integer (KHR_mesh_quantization's positions)
// as its value, or where the accessor is normalised mapped to [0, 1] (unsigned) or [−1, 1] (signed).
double number_at(const AccessorBytes& b, size_t i, int k) {
  if (b.component_type == kFloat) return float_at(b, i, k);
  const size_t size = size_t(tinygltf::GetComponentSizeInBytes(uint32_t(b.component_type)));
  const unsigned char* p = b.data + i * b.stride + size_t(k) * size;
  double value, largest;
  if (b.component_type == TINYGLTF_COMPONENT_TYPE_BYTE) {
    value = double(int8_t(*p)), largest = 127;
  } else if (b.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
    value = double(*p), largest = 255;
  } else if (b.component_type == TINYGLTF_COMPONENT_TYPE_SHORT) {
    int16_t v;
    std::memcpy(&v, p, sizeof v);
    value = double(v), largest = 32767;
  } else {
    uint16_t v;
    std::memcpy(&v, p, sizeof v);
    value = double(v), largest = 65535;
  }
  return b.normalized ? std::max(value / largest, -1.0) : value;
}

uint32_t index_at(const AccessorBytes& b, size_t i) {
  const unsigned char* p = b.data + i * b.stride;
  if (b.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) return *p;
  if (b.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
    uint16_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  uint32_t v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// The elements of VEC3 accessor `index` (`rule` allows it to be sparse or without a buffer view, whose
// elements are zeros), its sparse values put in at their indices (glTF 2.0 §3.6.2.3).
std::vector<Vec3> vec3_values(const tinygltf::Model& model, int index, const AccessorRule& rule,
                              const std::string& where, const std::string& what) {
  const AccessorBytes dense = accessor_bytes(model, index, rule, where, what);
  const auto vec3_at = [](const AccessorBytes& b, size_t i) {
    return Vec3(number_at(b, i, 0), number_at(b, i, 1), number_at(b, i, 2));
  };
  const tinygltf::Accessor& a = model.accessors[size_t(index)];
  const std::string name = where + ": " + what + " accessor " + std::to_string(index) + " sparse";
  if (a.sparse.isSparse && (a.sparse.count < 1 || size_t(a.sparse.count) > a.count))
    throw Error(name + " count " + std::to_string(a.sparse.count) + " is not from 1 to its " + std::to_string(a.count) +
                " elements");
  std::vector<Vec3> out(dense.count, Vec3::Zero());
  for (size_t i = 0; dense.data && i < dense.count; ++i) out[i] = vec3_at(dense, i);
  if (!a.sparse.isSparse) return out;
  // The indices and the values, each read as an accessor of its own over its buffer view.
  tinygltf::Accessor part;
  part.count = size_t(a.sparse.count);
  part.type = TINYGLTF_TYPE_SCALAR;
  part.componentType = a.sparse.indices.componentType;
  part.bufferView = a.sparse.indices.bufferView;
  part.byteOffset = size_t(a.sparse.indices.byteOffset);  // a negative one reads past its view
  if (part.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      part.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      part.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw Error(name + " indices have componentType " + std::to_string(part.componentType) +
                ", not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  const AccessorBytes indices = bytes_in_view(model, part, name + " indices");
  part.type = a.type, part.componentType = a.componentType, part.normalized = a.normalized;
  part.bufferView = a.sparse.values.bufferView;
  part.byteOffset = size_t(a.sparse.values.byteOffset);
  const AccessorBytes values = bytes_in_view(model, part, name + " values");
  for (size_t k = 0; k < indices.count; ++k) {
    const size_t i = index_at(indices, k);
    if (i >= out.size() || (k > 0 && i <= index_at(indices, k - 1)))
      throw Error(name + " index " + std::to_string(k) + " is " + std::to_string(i) +
                  (i >= out.size() ? ", past its " + std::to_string(out.size()) + " elements"
                                   : ", not above the index before it"));
    out[i] = vec3_at(values, k);
  }
  return out;
}

// A node's local transform: its matrix (column-major) or translation × rotation × scale.
Eigen::Matrix4d local_transform(const tinygltf::Node& node, const std::string& name) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16)
      throw Error(name + ": its matrix has " + std::to_string(node.matrix.size()) + " numbers, not 16");
    for (int k = 0; k < 16; ++k) m(k % 4, k / 4) = node.matrix[size_t(k)];
    return m;
  }
  const auto sized = [&](const std::vector<double>& v, size_t n, const char* what) {
    if (!v.empty() && v.size() != n)
      throw Error(name + ": its " + what + " has " + std::to_string(v.size()) + " numbers, not " + std::to_string(n));
    return !v.empty();
  };
  Eigen::Affine3d t = Eigen::Affine3d::Identity();
  if (sized(node.translation, 3, "translation"))
    t.translate(Vec3(node.translation[0], node.translation[1], node.translation[2]));
  if (sized(node.rotation, 4, "rotation")) {
    const Eigen::Quaterniond q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (!(q.norm() > 0.0)) throw Error(name + ": its rotation is not a rotation (zero or not finite)");
    t.rotate(q.normalized());
  }
  if (sized(node.scale, 3, "scale")) t.scale(Vec3(node.scale[0], node.scale[1], node.scale[2]));
  return t.matrix();
}

// A mesh placed by a node (or by none, where the file has no scene) at its world transform, with the
// weights of its morph targets: the node's where it gives them, else the mesh's (glTF 2.0 §3.7.2.2).
struct MeshInstance {
  int mesh = 0;
  Eigen::Matrix4d transform;
  std::vector<double> weights;
  std::string weights_of;  // whose weights they are, for messages ("node 1")
};

MeshInstance mesh_instance(const tinygltf::Model& model, int mesh, const Eigen::Matrix4d& transform, int node) {
  if (node >= 0 && !model.nodes[size_t(node)].weights.empty())
    return {mesh, transform, model.nodes[size_t(node)].weights, "node " + std::to_string(node)};
  return {mesh, transform, model.meshes[size_t(mesh)].weights, "mesh " + std::to_string(mesh)};
}

std::vector<MeshInstance> mesh_instances(const tinygltf::Model& model) {
  std::vector<MeshInstance> instances;
  if (model.scenes.empty()) {
    for (size_t m = 0; m < model.meshes.size(); ++m)
      instances.push_back(mesh_instance(model, int(m), Eigen::Matrix4d::Identity(), -1));
    return instances;
  }
  const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (size_t(scene) >= model.scenes.size())
    throw Error("the default scene " + std::to_string(scene) + " is not in the file");
  // Depth first through the node trees, each node at most once (the nodes of a scene form trees).
  std::vector<char> reached(model.nodes.size(), 0);
  std::vector<std::pair<int, Eigen::Matrix4d>> stack;
  // Pushed last first, so that the meshes come in the file's order (roots, then each node's children).
  const std::vector<int>& roots = model.scenes[size_t(scene)].nodes;
  for (auto root = roots.rbegin(); root != roots.rend(); ++root) stack.emplace_back(*root, Eigen::Matrix4d::Identity());
  while (!stack.empty()) {
    const auto [n, parent] = stack.back();
    stack.pop_back();
    const std::string name = "node " + std::to_string(n);
    if (n < 0 || size_t(n) >= model.nodes.size()) throw Error(name + " is not in the file");
    if (reached[size_t(n)]) throw Error(name + " is reached twice (the nodes of a scene must form trees)");
    reached[size_t(n)] = 1;
    const tinygltf::Node& node = model.nodes[size_t(n)];
    const Eigen::Matrix4d world = parent * local_transform(node, name);
    if (!world.allFinite()) throw Error(name + ": its world transform is not finite");
    if (node.mesh >= 0) {
      if (size_t(node.mesh) >= model.meshes.size())
        throw Error(name + " names mesh " + std::to_string(node.mesh) + ", which is not in the file");
      instances.push_back(mesh_instance(model, node.mesh, world, n));
    }
    for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) stack.emplace_back(*child, world);
  }
  return instances;
}

// The rules of the vertex attributes gpsurf drops (glTF 2.0 §3.7.2.1; KHR_mesh_quantization widens
// NORMAL to normalized BYTE and SHORT, TEXCOORD_n to any BYTE or SHORT, normalized or not).
struct DroppedAttributeRules {
  AccessorRule normal, texture_coordinates, colours;
};

DroppedAttributeRules dropped_attribute_rules(const tinygltf::Model& model) {
  const auto& used = model.extensionsUsed;
  constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUnsignedByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
  constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT, kUnsignedShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
  const AccessorRule colours{
      {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4}, {kFloat, kUnsignedByte, kUnsignedShort}, true, false};
  if (std::find(used.begin(), used.end(), "KHR_mesh_quantization") != used.end())
    return {{{TINYGLTF_TYPE_VEC3}, {kFloat, kByte, kShort}, true, false},
            {{TINYGLTF_TYPE_VEC2}, {kFloat, kByte, kUnsignedByte, kShort, kUnsignedShort}, false, false},
            colours};
  return {{{TINYGLTF_TYPE_VEC3}, {kFloat}, false, false},
          {{TINYGLTF_TYPE_VEC2}, {kFloat, kUnsignedByte, kUnsignedShort}, true, false},
          colours};
}

// Whether `name` is `prefix` and a set's index ("TEXCOORD_1"; up to 9 digits, so that it names itself safely).
bool is_set(const std::string& name, std::string_view prefix) {
  return name.size() > prefix.size() && name.size() <= prefix.size() + 9 && name.starts_with(prefix) &&
         std::all_of(name.begin() + std::ptrdiff_t(prefix.size()), name.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

// A primitive's vertex attributes that a covariance mesh does not hold, for the note: normals, every set
// of texture coordinates and of colours counted (each checked to be what glTF allows, one per position,
// as a reader of them would read it), others named.
void count_dropped_attributes(const tinygltf::Model& model, const tinygltf::Primitive& p,
                              const DroppedAttributeRules& rules, const std::string& where, size_t positions,
                              bool written_by_gpsurf, DroppedAttributes& dropped, std::set<std::string>& other) {
  for (const auto& [attribute, accessor] : p.attributes) {
    if (attribute == "POSITION" || attribute == kCovarianceAttribute) continue;
    const bool normal = attribute == "NORMAL", texture = is_set(attribute, "TEXCOORD_");
    if (!normal && !texture && !is_set(attribute, "COLOR_")) {
      other.insert(quoted_token(attribute));
      continue;
    }
    const AccessorRule& rule = normal ? rules.normal : texture ? rules.texture_coordinates : rules.colours;
    if (const size_t n = accessor_bytes(model, accessor, rule, where, attribute).count; n != positions)
      throw Error(where + ": " + attribute + " accessor " + std::to_string(accessor) + " has " + std::to_string(n) +
                  " elements for " + std::to_string(positions) + " positions");
    if (normal)
      dropped.normals += written_by_gpsurf ? 0 : positions;  // its own: the limit surface's again
    else
      (texture ? dropped.texture_coordinates : dropped.colours) += positions;
  }
}

// A primitive mode's name in glTF 2.0 (read_gltf_head has checked it is one of them).
std::string mode_name(int mode) {
  constexpr std::array<const char*, 7> kNames = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                                 "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
  return kNames.at(size_t(mode));
}

bool is_triangles(const tinygltf::Primitive& p) {
  return p.mode == TINYGLTF_MODE_TRIANGLES || p.mode == TINYGLTF_MODE_TRIANGLE_STRIP ||
         p.mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

// How far the instance's morph targets move each of primitive `p`'s `n` positions: Σ w_k times target
// k's POSITION (glTF 2.0 §3.7.2.2; float, or with KHR_mesh_quantization BYTE or SHORT), or nothing where
// no target with a nonzero weight has one. Targets of normals and tangents only move no position.
std::vector<Vec3> morph_displacements(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                      const MeshInstance& instance, const std::string& where, size_t n) {
  const std::vector<double>& weights = instance.weights;
  if (!weights.empty() && !p.targets.empty() && weights.size() != p.targets.size())
    throw Error(where + ": " + std::to_string(p.targets.size()) + " morph targets for the " +
                std::to_string(weights.size()) + " weights of " + instance.weights_of);
  const auto& used = model.extensionsUsed;
  std::vector<int> components{kFloat};
  if (std::find(used.begin(), used.end(), "KHR_mesh_quantization") != used.end())
    components.insert(components.end(), {TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT});
  const AccessorRule rule{{TINYGLTF_TYPE_VEC3}, components, false, false};
  std::vector<Vec3> moved;
  for (size_t t = 0; t < p.targets.size(); ++t) {
    const auto position = p.targets[t].find("POSITION");
    if (position == p.targets[t].end()) continue;
    const std::string what = "target " + std::to_string(t) + " POSITION";
    // Its count checked first: an accessor without a buffer view may claim any.
    if (const size_t count = model.accessors.at(size_t(position->second)).count; count != n)
      throw Error(where + ": " + what + " accessor " + std::to_string(position->second) + " has " +
                  std::to_string(count) + " elements for " + std::to_string(n) + " positions");
    const std::vector<Vec3> target = vec3_values(model, position->second, rule, where, what);
    const double w = t < weights.size() ? weights[t] : 0.0;
    if (w == 0.0) continue;
    moved.resize(n, Vec3::Zero());
    for (size_t i = 0; i < n; ++i) moved[i] += w * target[i];
  }
  return moved;
}

// The corners of the triangles of a primitive's `n` indexed vertices (glTF 2.0 §3.7.2.1: a strip's
// odd triangles reversed so that all turn the same way; a fan's around its first vertex).
template <class Emit>
void primitive_triangles(int mode, size_t n, const std::string& where, Emit&& emit) {
  if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < n; ++i) emit(i, i + 1 + i % 2, i + 2 - i % 2, true);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
    for (size_t i = 1; i + 1 < n; ++i) emit(i, i + 1, size_t(0), true);
  } else {
    if (n % 3 != 0) throw Error(where + ": " + std::to_string(n) + " vertices are not a whole number of triangles");
    for (size_t i = 0; i < n; i += 3) emit(i, i + 1, i + 2, false);
  }
}

// The bits of a position, +0 for −0, as the key of the weld.
struct PositionBits {
  std::array<uint64_t, 3> bits;
  bool operator==(const PositionBits&) const = default;
};
struct PositionBitsHash {
  size_t operator()(const PositionBits& p) const {
    uint64_t h = 0xcbf29ce484222325ull;
    for (const uint64_t b : p.bits) h = (h ^ b) * 0x100000001b3ull + (h >> 29);
    return size_t(h);
  }
};
PositionBits bits_of(const Vec3& p) {
  return {{std::bit_cast<uint64_t>(p.x() + 0.0), std::bit_cast<uint64_t>(p.y() + 0.0),
           std::bit_cast<uint64_t>(p.z() + 0.0)}};
}

}  // namespace

void check_gltf_head(std::string_view head, size_t size) {
  if (head.size() >= 4 && head.substr(0, 4) == "glTF") {
    if (head.size() < 12) throw Error("is a truncated .glb (" + std::to_string(size) + " bytes, its header has 12)");
    uint32_t version, length;
    std::memcpy(&version, head.data() + 4, 4);
    std::memcpy(&length, head.data() + 8, 4);
    if (version != 2) throw Error("is a .glb of version " + std::to_string(version) + ", not 2");
    if (length != size)
      throw Error("is a truncated or padded .glb (its header gives " + std::to_string(length) +
                  " bytes, the file has " + std::to_string(size) + ")");
    return;
  }
  const size_t start = head.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
  if (start == std::string_view::npos || head[start] != '{')
    throw Error("is neither a .glb (it does not begin with \"glTF\") nor glTF JSON (it does not begin with '{')");
}

PolygonSoup parse_gltf_soup(const std::string& data, const std::string& source, const std::string& base_dir,
                            bool& has_covariances) {
  has_covariances = false;
  const auto named = [&](const std::string& what) { return escaped(source) + ": " + what; };
  tinygltf::Model model;
  std::vector<MeshInstance> instances;
  std::vector<std::string> warnings;
  try {
    model = load_gltf_model(data, base_dir, warnings);
    instances = mesh_instances(model);
  } catch (const Error& e) {
    throw Error(named(e.what()), e.kind());
  }
  PolygonSoup soup;
  for (const std::string& line : warnings) soup.notes.push_back(named(line));
  // A primitive's positions and indices, each checked to lie in its buffer.
  const auto position_bytes = [&](const tinygltf::Primitive& p, const std::string& where) {
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) throw Error(where + ": has no POSITION attribute");
    return accessor_bytes(model, position->second,
                          {{TINYGLTF_TYPE_VEC3},
                           {kFloat, TINYGLTF_COMPONENT_TYPE_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                            TINYGLTF_COMPONENT_TYPE_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}},
                          where, "POSITION");
  };
  const auto index_bytes = [&](const tinygltf::Primitive& p, const std::string& where) {
    if (p.indices < 0) return AccessorBytes{};
    return accessor_bytes(model, p.indices,
                          {{TINYGLTF_TYPE_SCALAR},
                           {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT}},
                          where, "indices");
  };
  const auto where_of = [&](int mesh, size_t primitive) {
    return named("mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive));
  };
  // What the file would make, checked against the memory budget before it is read: each instance's
  // positions and corners (a corner may be a triangle of its own in a strip or fan). The counts are
  // those of accessors that lie in their buffers: a count a file's bytes cannot hold is refused as such.
  double positions = 0, corners = 0;
  size_t primitives = 0, with_covariances = 0;
  for (const MeshInstance& instance : instances) {
    const tinygltf::Mesh& mesh = model.meshes[size_t(instance.mesh)];
    for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const tinygltf::Primitive& p = mesh.primitives[pi];
      if (!is_triangles(p)) continue;
      ++primitives;
      if (p.attributes.count(kCovarianceAttribute)) ++with_covariances;
      const std::string where = where_of(instance.mesh, pi);
      const size_t n = position_bytes(p, where).count;
      positions += double(n);
      corners += double(p.indices >= 0 ? index_bytes(p, where).count : n);
    }
  }
  if (primitives == 0)
    throw Error(named("has no triangles (no mesh primitive of mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN)"));
  if (with_covariances != 0 && with_covariances != primitives)
    throw Error(named(std::to_string(with_covariances) + " of " + std::to_string(primitives) +
                      " triangle primitives have _COVARIANCE: all or none must"));
  has_covariances = with_covariances != 0;
  // Per position its vector, covariance and weld entry; per corner its index and a face offset.
  check_output_size(
      {positions, corners, positions * double(sizeof(Vec3) + (has_covariances ? sizeof(Mat3) : 0) + 48) + corners * 16},
      escaped(source), "triangles", "the file is too large to read here");

  DroppedAttributes dropped;
  std::set<std::string> other_attributes;
  std::map<int, size_t> other_primitives;  // by mode, the primitives without triangles
  // The vertex at each position of the current mesh instance: glTF splits a corner at its seams, and
  // exporters split a mesh into primitives by material, their borders' corners in each; the weld stays
  // within the instance (other nodes place vertex sets of their own, as OBJ objects are).
  std::unordered_map<PositionBits, int, PositionBitsHash> welded;
  const bool written_by_gpsurf = model.asset.generator == kGenerator;
  const DroppedAttributeRules rules = dropped_attribute_rules(model);
  std::vector<int> vertex_of;  // the welded vertex of each position of the current primitive
  std::vector<int> verts;
  std::vector<int> offsets{0};
  for (const MeshInstance& instance : instances) {
    const tinygltf::Mesh& mesh = model.meshes[size_t(instance.mesh)];
    const Eigen::Matrix3d linear = instance.transform.topLeftCorner<3, 3>();
    const Vec3 shift = instance.transform.topRightCorner<3, 1>();
    // A world transform that mirrors turns the triangles' winding around (glTF 2.0, "Transformations"):
    // they are read reversed, so that the faces stay outward.
    const bool mirrored = linear.determinant() < 0;
    welded.clear();
    for (size_t pi = 0; pi < mesh.primitives.size(); ++pi) {
      const tinygltf::Primitive& p = mesh.primitives[pi];
      if (!is_triangles(p)) {
        ++other_primitives[p.mode];
        continue;
      }
      const std::string where = where_of(instance.mesh, pi);
      const AccessorBytes points = position_bytes(p, where);
      count_dropped_attributes(model, p, rules, where, points.count, written_by_gpsurf, dropped, other_attributes);
      AccessorBytes gaussians;
      if (has_covariances)
        gaussians = accessor_bytes(model, p.attributes.at(kCovarianceAttribute), {{TINYGLTF_TYPE_MAT3}, {kFloat}},
                                   where, kCovarianceAttribute);
      if (has_covariances && gaussians.count != points.count)
        throw Error(where + ": " + std::to_string(gaussians.count) + " covariances for " +
                    std::to_string(points.count) + " positions");
      const std::vector<Vec3> moved = morph_displacements(model, p, instance, where, points.count);
      vertex_of.assign(points.count, 0);
      for (size_t i = 0; i < points.count; ++i) {
        Vec3 local(number_at(points, i, 0), number_at(points, i, 1), number_at(points, i, 2));
        if (!moved.empty()) local += moved[i];
        const Vec3 world = linear * local + shift;
        if (const std::string why = position_problem(world); !why.empty())
          throw Error(where + ": vertex " + std::to_string(i) + " " + why);
        // gpsurf writes a vertex per Gaussian, none split at a seam: its files' vertices stay apart,
        // also those a repair or a split op left at one position.
        const auto [found, added] = written_by_gpsurf ? std::pair{welded.end(), true}
                                                      : welded.emplace(bits_of(world), int(soup.positions.size()));
        vertex_of[i] = added ? int(soup.positions.size()) : found->second;
        if (!added) continue;
        soup.positions.push_back(world);
        if (!has_covariances) continue;
        Mat3 sigma;
        for (int k = 0; k < 9; ++k) sigma(k % 3, k / 3) = float_at(gaussians, i, k);
        sigma = linear * sigma * linear.transpose();
        if (const std::string why = covariance_problem(sigma); !why.empty())
          throw Error(where + ": vertex " + std::to_string(i) + " _COVARIANCE " + why);
        // Kept as the check read it, its lower triangle mirrored: a matrix symmetric only within
        // rounding would otherwise be saved (upper triangle) as another, which the check may refuse.
        soup.covariances.push_back(sigma.selfadjointView<Eigen::Lower>());
      }
      const AccessorBytes indices = index_bytes(p, where);
      const size_t n = p.indices >= 0 ? indices.count : points.count;
      const auto vertex = [&](size_t k) {
        const size_t i = indices.data ? index_at(indices, k) : k;
        if (i >= points.count)
          throw Error(where + ": index " + std::to_string(k) + " is " + std::to_string(i) + ", past its " +
                      std::to_string(points.count) + " positions");
        return vertex_of[i];
      };
      primitive_triangles(p.mode, n, where, [&](size_t a, size_t b, size_t c, bool skip_degenerate) {
        int t[3] = {vertex(a), vertex(b), vertex(c)};
        // A strip or fan restarts through triangles with a repeated corner: they are not faces.
        if (skip_degenerate && (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])) return;
        if (mirrored) std::swap(t[1], t[2]);
        verts.insert(verts.end(), t, t + 3);
        offsets.push_back(int(verts.size()));
      });
    }
  }
  dropped.other.push_back(named_list("vertex attribute", "vertex attributes",
                                     std::vector<std::string>(other_attributes.begin(), other_attributes.end())));
  if (dropped.other.back().empty()) dropped.other.pop_back();
  for (const auto& [mode, count] : other_primitives)
    dropped.other.push_back(std::to_string(count) + " " + mode_name(mode) +
                            (count == 1 ? " primitive" : " primitives"));
  if (std::string note = dropped_attributes_note(escaped(source), dropped); !note.empty())
    soup.notes.push_back(std::move(note));
  soup.faces.n_vertices = int(soup.positions.size());
  soup.faces.verts = std::move(verts);
  soup.faces.offsets = std::move(offsets);
  return soup;
}

GltfTriangles gltf_triangles_of(const CovarianceMesh& mesh) {
  GltfTriangles out;
  Diagonals diagonals;
  out.positions.reserve(mesh.n_vertices());
  for (size_t i = 0; i < mesh.n_vertices(); ++i) out.positions.push_back(mesh.mean(i));
  out.covariances = mesh.covariances;
  out.normals.assign(mesh.n_vertices(), Vec3::Zero());
  for (size_t f = 0; f < mesh.n_faces(); ++f) {
    const std::span<const int> corners = mesh.face(f);
    // Newell's normal: its length is twice the face's area, so that the sum weighs faces by area.
    Vec3 normal = Vec3::Zero();
    for (size_t k = 0; k < corners.size(); ++k)
      normal += out.positions[size_t(corners[k])].cross(out.positions[size_t(corners[(k + 1) % corners.size()])]);
    for (const int v : corners) out.normals[size_t(v)] += normal;
    triangulate_face(mesh, corners, out.positions, normal, diagonals, out.triangles);
  }
  // glTF's normals are unit vectors: a vertex whose faces have no area gets +z.
  for (Vec3& n : out.normals) n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitZ();
  return out;
}

namespace {

// Appends `values` to the buffer as one buffer view (4-byte aligned, as every value written is 4 bytes)
// and an accessor of `count` elements over it; returns the accessor's index.
int add_accessor(tinygltf::Model& model, const std::vector<float>& floats, const std::vector<uint32_t>& indices,
                 size_t count, int type, int target) {
  std::vector<unsigned char>& buffer = model.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  const unsigned char* bytes = floats.empty() ? reinterpret_cast<const unsigned char*>(indices.data())
                                              : reinterpret_cast<const unsigned char*>(floats.data());
  view.byteLength = floats.empty() ? indices.size() * sizeof(uint32_t) : floats.size() * sizeof(float);
  view.target = target;
  buffer.insert(buffer.end(), bytes, bytes + view.byteLength);
  model.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = int(model.bufferViews.size()) - 1;
  accessor.componentType = floats.empty() ? TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT : kFloat;
  accessor.count = count;
  accessor.type = type;
  model.accessors.push_back(accessor);
  return int(model.accessors.size()) - 1;
}

}  // namespace

void write_gltf(std::ostream& out, const GltfTriangles& mesh, bool binary) {
  const size_t n = mesh.positions.size();
  if (n > size_t(std::numeric_limits<int>::max())) throw Error("not written: too many vertices for glTF");
  std::vector<float> positions, normals, covariances;
  positions.reserve(3 * n);
  normals.reserve(3 * n);
  std::vector<double> low(3, std::numeric_limits<double>::infinity()),
      high(3, -std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) {
      const float x = float(mesh.positions[i][k]);
      if (!std::isfinite(x)) throw Error("not written: vertex " + std::to_string(i) + " position does not fit a float");
      positions.push_back(x);
      normals.push_back(float(mesh.normals[i][k]));
      low[size_t(k)] = std::min(low[size_t(k)], double(x));
      high[size_t(k)] = std::max(high[size_t(k)], double(x));
    }
  for (size_t i = 0; i < mesh.covariances.size(); ++i) {
    const Mat3 in_float = mesh.covariances[i].cast<float>().cast<double>();
    if (const std::string why = covariance_problem(in_float); !why.empty())
      throw Error("not written: vertex " + std::to_string(i) + " covariance rounded to float " + why + " (write .ply)");
    for (int k = 0; k < 9; ++k) covariances.push_back(float(in_float(k % 3, k / 3)));
  }
  std::vector<uint32_t> indices;
  indices.reserve(3 * mesh.triangles.size());
  for (const auto& t : mesh.triangles) indices.insert(indices.end(), t.begin(), t.end());

  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = kGenerator;
  model.buffers.resize(1);
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  primitive.attributes["POSITION"] =
      add_accessor(model, positions, {}, n, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  model.accessors.back().minValues = low;
  model.accessors.back().maxValues = high;
  primitive.attributes["NORMAL"] =
      add_accessor(model, normals, {}, n, TINYGLTF_TYPE_VEC3, TINYGLTF_TARGET_ARRAY_BUFFER);
  if (!covariances.empty())
    primitive.attributes[kCovarianceAttribute] =
        add_accessor(model, covariances, {}, n, TINYGLTF_TYPE_MAT3, TINYGLTF_TARGET_ARRAY_BUFFER);
  primitive.indices =
      add_accessor(model, {}, indices, indices.size(), TINYGLTF_TYPE_SCALAR, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  model.meshes.resize(1);
  model.meshes[0].primitives.push_back(primitive);
  model.nodes.resize(1);
  model.nodes[0].mesh = 0;
  model.scenes.resize(1);
  model.scenes[0].nodes.push_back(0);
  model.defaultScene = 0;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, !binary, binary))
    throw Error("not written: tinygltf refused the mesh");
}

}  // namespace gps
