#pragma once
// The top of a glTF file's JSON, read before tinygltf reads the file: its version, the extensions it
// requires (its "extensionsRequired", glTF 2.0 §3.12: a reader must refuse a file that needs one it does
// not know, rather than read it wrong), the files its buffers name, and its meshes' primitives, morph
// weights and accessors checked as glTF defines them (tinygltf drops a primitive it cannot read without a word,
// and refuses an accessor in its own words).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gps {

/// Whether gpsurf's glTF reader reads files that require extension `name`: KHR_mesh_quantization (integer
/// positions), and the extensions that change only how a surface looks (materials, textures, lights),
/// which it does not read at all.
bool reads_gltf_extension(std::string_view name);

struct GltfHead {
  std::vector<std::string> buffer_uris;      // the buffers' uris that name files (not data: URIs), as written
  std::optional<size_t> buffer_without_uri;  // the first buffer without a uri (a .glb's BIN chunk holds it)
};

/// The head of the glTF JSON `json_text`. Throws gps::Error, without the file's name, for a version
/// other than 2.x, for the first extension the file requires and gpsurf does not read (naming it, and
/// what to do where it is a compression), for JSON nested deeper than kMaxJsonDepth, for an accessor
/// whose componentType, type or count glTF has not ("accessor 2: componentType 9999 is none of
/// glTF's …"), for a primitive without attributes, with an attribute, indices or a morph target's
/// attribute that name no accessor of the file, or with a mode glTF has not ("mesh 0 primitive 1: mode
/// 7 is none of glTF's …"), and for a mesh's or node's morph weights that are not numbers. Text that is
/// not valid JSON passes: the reader refuses it with its own words.
GltfHead read_gltf_head(std::string_view json_text);

/// A uri's path as RFC 3986 decodes it: %XX escapes only ('+' stays a plus).
std::string uri_decoded(std::string_view uri);
/// The same as a web form decodes it, as tinygltf does: '+' a space, '%' and any two characters a byte.
std::string uri_form_decoded(std::string_view uri);

}  // namespace gps
