#include "core/io/gltf_head.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
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

GltfHead read_gltf_head(std::string_view json_text) {
  // Only the top level's "asset", "extensionsRequired" and the buffers' file uris are kept while
  // parsing: the rest (base64 buffers among it) is read past, not held.
  bool kept = false;
  const nlohmann::json::parser_callback_t keep_head = [&](int depth, nlohmann::json::parse_event_t event,
                                                          nlohmann::json& parsed) {
    // tinygltf reads "extras" recursively: text nested past its stack is refused here first.
    if (size_t(depth) > kMaxJsonDepth)
      throw Error("is glTF JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
    if (depth == 1 && event == nlohmann::json::parse_event_t::key) {
      kept = parsed == "extensionsRequired" || parsed == "asset" || parsed == "buffers";
      return kept;
    }
    // A buffer's embedded data (a data: URI) is dropped as soon as it is read.
    if (event == nlohmann::json::parse_event_t::value && parsed.is_string() &&
        parsed.get_ref<const std::string&>().starts_with("data:"))
      return false;
    return depth == 0 || kept;
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
  if (const auto buffers = top.find("buffers"); buffers != top.end() && buffers->is_array())
    for (const nlohmann::json& buffer : *buffers)
      if (buffer.is_object())
        if (const auto uri = buffer.find("uri"); uri != buffer.end() && uri->is_string())
          head.buffer_uris.push_back(uri->get<std::string>());
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
