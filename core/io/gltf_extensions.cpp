#include "core/io/gltf_extensions.h"

#include <nlohmann/json.hpp>

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

void check_required_gltf_extensions(std::string_view json_text) {
  // Only the top level's "extensionsRequired" is kept while parsing: the rest (base64 buffers among
  // it) is read past, not held.
  bool in_required = false;
  const nlohmann::json::parser_callback_t keep_required = [&](int depth, nlohmann::json::parse_event_t event,
                                                              nlohmann::json& parsed) {
    // tinygltf reads "extras" recursively: text nested past its stack is refused here first.
    if (size_t(depth) > kMaxJsonDepth)
      throw Error("is glTF JSON nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
    if (depth == 1 && event == nlohmann::json::parse_event_t::key) {
      in_required = parsed == "extensionsRequired";
      return in_required;
    }
    return depth == 0 || in_required;
  };
  const nlohmann::json top = nlohmann::json::parse(json_text.begin(), json_text.end(), keep_required, false);
  if (!top.is_object()) return;
  const auto required = top.find("extensionsRequired");
  if (required == top.end() || !required->is_array()) return;
  for (const nlohmann::json& extension : *required) {
    if (!extension.is_string()) continue;
    const std::string name = extension.get<std::string>();
    if (reads_gltf_extension(name)) continue;
    const bool compression = name == "KHR_draco_mesh_compression" || name == "EXT_meshopt_compression";
    throw Error("requires the glTF extension " + quoted_token(name) + ", which gpsurf does not read" +
                (compression ? " (export the file without mesh compression)" : ""));
  }
}

}  // namespace gps
