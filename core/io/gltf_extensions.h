#pragma once
// The glTF extensions a file requires (its "extensionsRequired", glTF 2.0 §3.12): a reader must refuse a
// file that needs one it does not know, rather than read it wrong.
#include <string_view>

namespace gps {

/// Whether gpsurf's glTF reader reads files that require extension `name`: KHR_mesh_quantization (integer
/// positions), and the extensions that change only how a surface looks (materials, textures, lights),
/// which it does not read at all.
bool reads_gltf_extension(std::string_view name);

/// Throws gps::Error, without the file's name, for the first extension that the glTF JSON `json_text`
/// requires and gpsurf does not read, naming it (and what to do where it is a compression), and for
/// JSON nested deeper than kMaxJsonDepth. Text that is not valid JSON passes: the reader refuses it
/// with its own words.
void check_required_gltf_extensions(std::string_view json_text);

}  // namespace gps
