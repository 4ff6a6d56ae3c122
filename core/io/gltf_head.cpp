#include "core/io/gltf_head.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "core/io/json_text.h"
#include "core/support/error.h"
#include "core/support/quoted_text.h"

namespace gps {

bool reads_gltf_extension(std::string_view name) {
  if (name == "KHR_mesh_quantization") return true;
  constexpr std::array<std::string_view, 5> kLooks = {"KHR_materials_", "KHR_texture_", "EXT_texture_", "KHR_lights_",
                                                      "EXT_lights_"};
  for (const std::string_view prefix : kLooks)
    if (name.substr(0, prefix.size()) == prefix) return true;
  return false;
}

namespace {

// A JSON value of the file as a message shows it: a string quoted (escaped, cut), anything else as
// json_shown does ("1.5", "a null").
std::string shown(const nlohmann::json& value) {
  return value.is_string() ? quoted_token(value.get_ref<const std::string&>()) : json_shown(value);
}

// The element `index` of the array `elements`, named `name` ("accessor 2"), which must be an object.
const nlohmann::json& object_at(const nlohmann::json& elements, size_t index, const std::string& name) {
  const nlohmann::json& element = elements[index];
  if (!element.is_object()) throw Error(name + " is " + shown(element) + ", not an object");
  return element;
}

// An accessor a primitive names (`what`: "attribute 'NORMAL'", "indices"), among the file's `accessors`.
void check_accessor_reference(const nlohmann::json& value, size_t accessors, const std::string& where,
                              const std::string& what) {
  if (!value.is_number_unsigned())
    throw Error(where + ": " + what + " is " + shown(value) + ", not an accessor's index");
  if (value.get<uint64_t>() >= accessors)
    throw Error(where + ": " + what + " names accessor " + value.dump() + ", which is not in the file");
}

// The morph target weights of a mesh or node (`name`: "node 2"), which must be numbers: tinygltf reads
// them only up to the first that is not, and weights that are no array as none.
void check_weights(const nlohmann::json& element, const std::string& name) {
  const auto weights = element.find("weights");
  if (weights == element.end()) return;
  if (!weights->is_array()) throw Error(name + ": weights is " + shown(*weights) + ", not an array");
  for (size_t k = 0; k < weights->size(); ++k)
    if (!(*weights)[k].is_number())
      throw Error(name + ": weight " + std::to_string(k) + " is " + shown((*weights)[k]) + ", not a number");
}

// Each mesh's primitives as glTF 2.0 defines them: tinygltf drops a primitive whose attributes it cannot
// read (its geometry lost without a word), reads indices or a mode that are not integers as absent, and
// keeps a mode glTF has not; it drops a morph target that is not an object, renumbering those after it,
// and an attribute of one that is not an integer.
void check_primitives(const nlohmann::json& meshes, size_t accessors) {
  for (size_t m = 0; m < meshes.size(); ++m) {
    const std::string mesh_name = "mesh " + std::to_string(m);
    const nlohmann::json& mesh = object_at(meshes, m, mesh_name);
    check_weights(mesh, mesh_name);
    const auto primitives = mesh.find("primitives");
    if (primitives == mesh.end()) throw Error(mesh_name + " has no primitives");
    if (!primitives->is_array()) throw Error(mesh_name + ": primitives is " + shown(*primitives) + ", not an array");
    for (size_t p = 0; p < primitives->size(); ++p) {
      const std::string where = mesh_name + " primitive " + std::to_string(p);
      const nlohmann::json& primitive = object_at(*primitives, p, where);
      const auto attributes = primitive.find("attributes");
      if (attributes == primitive.end()) throw Error(where + " has no attributes");
      if (!attributes->is_object()) throw Error(where + ": attributes is " + shown(*attributes) + ", not an object");
      for (const auto& [name, accessor] : attributes->items())
        check_accessor_reference(accessor, accessors, where, "attribute " + quoted_token(name));
      if (const auto indices = primitive.find("indices"); indices != primitive.end())
        check_accessor_reference(*indices, accessors, where, "indices");
      if (const auto targets = primitive.find("targets"); targets != primitive.end()) {
        if (!targets->is_array()) throw Error(where + ": targets is " + shown(*targets) + ", not an array");
        for (size_t t = 0; t < targets->size(); ++t) {
          const std::string target = "target " + std::to_string(t);
          for (const auto& [name, accessor] : object_at(*targets, t, where + " " + target).items())
            check_accessor_reference(accessor, accessors, where, target + " attribute " + quoted_token(name));
        }
      }
      if (const auto mode = primitive.find("mode");
          mode != primitive.end() && !(mode->is_number_unsigned() && mode->get<uint64_t>() <= 6))
        throw Error(where + ": mode " + shown(*mode) + " is none of glTF's (0 POINTS to 6 TRIANGLE_FAN)");
    }
  }
}

// Each accessor's componentType, type and count as glTF 2.0 defines them, said here in gpsurf's words
// (tinygltf refuses them in its own).
void check_accessors(const nlohmann::json& accessors) {
  constexpr std::array<uint64_t, 6> kComponentTypes = {5120, 5121, 5122, 5123, 5125, 5126};
  constexpr std::array<std::string_view, 7> kTypes = {"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"};
  for (size_t i = 0; i < accessors.size(); ++i) {
    const std::string name = "accessor " + std::to_string(i);
    const nlohmann::json& accessor = object_at(accessors, i, name);
    const auto member = [&](const char* key) {
      const auto it = accessor.find(key);
      if (it == accessor.end()) throw Error(name + " has no " + key);
      return *it;
    };
    const nlohmann::json component_type = member("componentType");
    if (!component_type.is_number_unsigned() || std::find(kComponentTypes.begin(), kComponentTypes.end(),
                                                          component_type.get<uint64_t>()) == kComponentTypes.end())
      throw Error(name + ": componentType " + shown(component_type) +
                  " is none of glTF's (5120, 5121, 5122, 5123, 5125 and 5126)");
    const nlohmann::json type = member("type");
    if (!type.is_string() ||
        std::find(kTypes.begin(), kTypes.end(), type.get_ref<const std::string&>()) == kTypes.end())
      throw Error(name + ": type " + shown(type) +
                  " is none of glTF's (SCALAR, VEC2, VEC3, VEC4, MAT2, MAT3 and MAT4)");
    const nlohmann::json count = member("count");
    if (!count.is_number_unsigned() || count.get<uint64_t>() == 0)
      throw Error(name + ": count " + shown(count) + " is not a count of elements (1 or more)");
  }
}

// The array `key` of the top-level object, or an empty one where the file has none (or not an array,
// which tinygltf reads as none).
const nlohmann::json& array_of(const nlohmann::json& top, const char* key) {
  static const nlohmann::json none = nlohmann::json::array();
  const auto it = top.find(key);
  return it != top.end() && it->is_array() ? *it : none;
}

}  // namespace

GltfHead read_gltf_head(std::string_view json_text) {
  // Only the top level's "asset", "extensionsRequired", the buffers' file uris, the meshes, the nodes and
  // the accessors are kept while parsing: the rest (base64 buffers among it) is read past, not held.
  constexpr std::array<std::string_view, 6> kKept = {"asset", "extensionsRequired", "buffers", "meshes",
                                                     "nodes", "accessors"};
  std::string section;  // the top-level member being parsed
  const nlohmann::json::parser_callback_t keep_head = [&](int depth, nlohmann::json::parse_event_t event,
                                                          nlohmann::json& parsed) {
    // tinygltf reads "extras" recursively: text nested past its stack is refused here first.
    if (size_t(depth) > kMaxJsonDepth)
      throw Error("is glTF JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
    if (depth == 1 && event == nlohmann::json::parse_event_t::key) {
      section = parsed.get<std::string>();
      return std::find(kKept.begin(), kKept.end(), section) != kKept.end();
    }
    // A buffer's embedded data (a data: URI) is cut to its scheme as soon as it is read.
    if (section == "buffers" && event == nlohmann::json::parse_event_t::value && parsed.is_string() &&
        parsed.get_ref<const std::string&>().starts_with("data:"))
      parsed = "data:";
    return depth == 0 || std::find(kKept.begin(), kKept.end(), section) != kKept.end();
  };
  const nlohmann::json top = nlohmann::json::parse(json_text.begin(), json_text.end(), keep_head, false);
  GltfHead head;
  if (!top.is_object()) return head;
  if (const auto asset = top.find("asset"); asset != top.end() && asset->is_object())
    if (const auto version = asset->find("version"); version != asset->end() && version->is_string()) {
      const std::string v = version->get<std::string>();
      if (!v.starts_with("2."))
        throw Error("is glTF " + quoted_token(v) + "; gpsurf reads glTF 2.0 (convert the file, e.g. with Blender)");
    }
  if (const auto required = top.find("extensionsRequired"); required != top.end() && required->is_array())
    for (const nlohmann::json& extension : *required) {
      if (!extension.is_string()) continue;
      const std::string name = extension.get<std::string>();
      if (reads_gltf_extension(name)) continue;
      const bool compression = name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression";
      throw Error("requires the glTF extension " + quoted_token(name) + ", which gpsurf does not read" +
                  (compression ? " (export the file without mesh compression)" : ""));
    }
  const nlohmann::json& buffers = array_of(top, "buffers");
  for (size_t b = 0; b < buffers.size(); ++b) {
    if (!buffers[b].is_object()) continue;
    if (const auto uri = buffers[b].find("uri"); uri != buffers[b].end() && uri->is_string() && !uri->empty()) {
      if (*uri != "data:") head.buffer_uris.push_back(uri->get<std::string>());
    } else if (!head.buffer_without_uri) {
      head.buffer_without_uri = b;
    }
  }
  const nlohmann::json& accessors = array_of(top, "accessors");
  check_accessors(accessors);
  check_primitives(array_of(top, "meshes"), accessors.size());
  const nlohmann::json& nodes = array_of(top, "nodes");
  for (size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].is_object()) check_weights(nodes[n], "node " + std::to_string(n));
  return head;
}

namespace {

// A hex digit's value, or −1.
int hex_value(char c) {
  return c >= '0' && c <= '9'   ? c - '0'
         : c >= 'a' && c <= 'f' ? c - 'a' + 10
         : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                : -1;
}

}  // namespace

std::string uri_decoded(std::string_view uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && hex_value(uri[i + 1]) >= 0 && hex_value(uri[i + 2]) >= 0) {
      out += char(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

std::string uri_form_decoded(std::string_view uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && i + 2 < uri.size()) {  // any two characters, a digit that is none as 0
      out += char(std::max(hex_value(uri[i + 1]), 0) * 16 + std::max(hex_value(uri[i + 2]), 0));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

}  // namespace gps
