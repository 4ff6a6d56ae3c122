#pragma once
// A glTF file's model as tinygltf reads it, in gpsurf's words: its head checked first (core/io/gltf_head.h),
// a .glb's chunks checked, buffer files read from the .gltf's folder only and by their uris' own
// decoding, images that cannot be decoded read past, and tinygltf's messages said as gpsurf says them.
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace gps {

/// The model of the glTF file whose bytes are `data` (a .glb or a .gltf's JSON), its buffer files read
/// from the folder `base_dir` (none where empty). Notes on what was read past (images missing or not
/// decodable) are added to `notes`. Throws gps::Error, without the file's name, where it cannot be read.
tinygltf::Model load_gltf_model(const std::string& data, const std::string& base_dir, std::vector<std::string>& notes);

}  // namespace gps
