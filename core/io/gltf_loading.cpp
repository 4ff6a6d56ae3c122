#include "core/io/gltf_loading.h"

#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <optional>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "core/io/gltf_head.h"
#include "core/io/text_file.h"
#include "core/support/error.h"
#include "core/support/memory_budget.h"
#include "core/support/quoted_text.h"

namespace gps {

namespace {

// The first line of a tinygltf message, without its trailing full stop or spaces.
std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  while (!line.empty() && (line.back() == ' ' || line.back() == '.' || line.back() == '\r')) line.pop_back();
  return escaped(line);
}

// A name that a tinygltf message ends with (its one line break after it taken off), shown quoted whole.
std::string name_at_end(std::string text) {
  if (text.ends_with('\n')) text.pop_back();
  return quoted_token(text);
}

// The part of `text` after `prefix` up to `end` ("" where either is not there).
std::string between(const std::string& text, const std::string& prefix, const std::string& end) {
  if (text.rfind(prefix, 0) != 0) return "";
  const size_t stop = text.find(end, prefix.size());
  return stop == std::string::npos ? "" : text.substr(prefix.size(), stop - prefix.size());
}

// tinygltf's and nlohmann's errors that a user meets, in our words; others as they come (first_line).
std::string loader_error(const std::string& text) {
  if (text.rfind("[json.exception.parse_error", 0) == 0) {
    const size_t at = text.find(" at line ");
    const size_t end = at == std::string::npos ? at : text.find(':', at);
    return "is not valid glTF JSON" + (end == std::string::npos ? "" : " (" + text.substr(at + 4, end - at - 4) + ")");
  }
  if (text.rfind("Failed to decode 'uri'", 0) == 0)
    return "has a buffer whose embedded data (its data: URI) is not base64 or does not hold its byteLength in bytes";
  if (const std::string missing = "File not found : "; text.rfind(missing, 0) == 0)
    return "names a buffer file " + name_at_end(text.substr(missing.size())) +
           " that is not there (buffer files are read from the .gltf's folder)";
  if (const std::string read = "File read error : "; text.rfind(read, 0) == 0) {
    const size_t ours = text.find(" : ", read.size());  // tinygltf's path, then read_buffer_file's words
    return "names a buffer file that cannot be read: " +
           first_line(ours == std::string::npos ? text : text.substr(ours + 3));
  }
  if (const std::string size = "File size mismatch : "; text.rfind(size, 0) == 0) {
    const std::string path = between(text, size, ", requestedBytes ");
    const std::string wanted = between(text, size + path + ", requestedBytes ", ", but got ");
    const size_t got = text.find(", but got ");
    return "names a buffer file " + quoted_token(std::filesystem::path(path).filename().string()) + " of " +
           first_line(got == std::string::npos ? "" : text.substr(got + 10)) + " bytes where its byteLength is " +
           first_line(wanted);
  }
  if (text.rfind("Invalid `byteLength'. Must be equal or less than binary size", 0) == 0)
    return "has a buffer whose byteLength is more than the .glb's BIN chunk holds";
  if (const std::string accessor = between(text, "accessor[", "] invalid bufferView"); !accessor.empty())
    return "has accessor " + first_line(accessor) + " (a primitive's indices) without a buffer view in the file";
  if (text.rfind("JSON string too short", 0) == 0) return "is too short to be a glTF file";
  if (text.rfind("\"asset\" object not found", 0) == 0)
    return "has no \"asset\" object (a glTF file names its version there: \"asset\": {\"version\": \"2.0\"})";
  if (text.rfind("Invalid `byteStride' value", 0) == 0)
    return "has a bufferView whose byteStride is not a multiple of 4 from 4 to 252 (glTF's rule), got" +
           first_line(text.substr(text.rfind(':') + 1));
  return first_line(text);
}

// The folder a .gltf's buffer files are read from, and the paths tinygltf asks for that it decoded
// as a form decodes them ('+' as a space), each with the file its uri names.
struct BufferFolder {
  std::string folder;
  std::unordered_map<std::string, std::string> renamed;

  bool holds(const std::string& path) const { return path.size() > folder.size() && path.starts_with(folder + "/"); }
};

// tinygltf reads a .gltf's buffer files through these: only regular files in the .gltf's folder (never
// the working folder, where tinygltf looks next), no "~" expansion, nothing at all where the data came
// without a folder.
bool regular_file_exists(const std::string& path, void* folder) {
  std::error_code error;
  return folder != nullptr && static_cast<const BufferFolder*>(folder)->holds(path) &&
         std::filesystem::is_regular_file(path, error);
}
std::string path_named(const std::string& path, void* folder) {
  if (folder == nullptr) return path;
  const auto& renamed = static_cast<const BufferFolder*>(folder)->renamed;
  const auto it = renamed.find(path);
  return it == renamed.end() ? path : it->second;
}
bool read_buffer_file(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* folder) {
  if (folder == nullptr || !static_cast<const BufferFolder*>(folder)->holds(path)) return false;
  try {
    std::error_code error;
    const uintmax_t size = std::filesystem::file_size(path, error);
    if (!error && size > memory_limit_bytes() / 2) {
      if (err)
        *err += quoted_token(std::filesystem::path(path).filename().string()) + ": " + std::to_string(size) +
                " bytes, more than the memory budget lets a buffer hold";
      return false;
    }
    const std::string bytes = read_text_file(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const Error& e) {
    if (err) *err += e.what();
    return false;
  }
}
bool write_nothing(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// Images are not read: a mesh's surface needs none of them.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// A .glb's chunks (glTF 2.0 §4.4): the JSON chunk, then at most a BIN chunk, each inside the file; whether
// the BIN chunk is there. tinygltf checks the BIN chunk's length without its 8-byte header, so a chunk that
// claims those bytes is refused here.
bool check_glb_chunks(const std::string& data) {
  const auto word = [&](size_t at) {
    uint32_t w;
    std::memcpy(&w, data.data() + at, 4);
    return uint64_t(w);
  };
  if (data.size() < 20)
    throw Error("is a truncated .glb (" + std::to_string(data.size()) + " bytes, with its JSON chunk's header 20)");
  const auto type_name = [&](size_t at) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08X", unsigned(word(at)));
    return std::string(hex);
  };
  constexpr uint64_t kJson = 0x4E4F534A, kBin = 0x004E4942;
  const uint64_t json_end = 20 + word(12);
  if (json_end > data.size())
    throw Error("is a truncated .glb (its JSON chunk ends at byte " + std::to_string(json_end) + " of " +
                std::to_string(data.size()) + ")");
  if (word(16) != kJson)
    throw Error("is a .glb whose first chunk is not its JSON (its type is " + type_name(16) + ", JSON's 0x4E4F534A)");
  if (word(12) == 0) throw Error("is a .glb whose JSON chunk is empty");
  if (json_end == data.size()) return false;
  if (json_end + 8 > data.size())
    throw Error("is a truncated .glb (" + std::to_string(data.size() - json_end) +
                " bytes after its JSON chunk, too few for a chunk's header)");
  const uint64_t bin_end = json_end + 8 + word(json_end);
  if (bin_end > data.size())
    throw Error("is a truncated .glb (its BIN chunk ends at byte " + std::to_string(bin_end) + " of " +
                std::to_string(data.size()) + ")");
  if (word(json_end + 4) != kBin)
    throw Error("is a .glb whose second chunk is not BIN (its type is " + type_name(json_end + 4) +
                ", BIN's 0x004E4942)");
  if (word(json_end) < 4 || word(json_end) % 4 != 0)
    throw Error("is a .glb whose BIN chunk holds " + std::to_string(word(json_end)) +
                " bytes: a multiple of 4, at least 4 (a .glb without binary data leaves the chunk out)");
  return true;
}

// The JSON chunk of a .glb (check_glb_chunks has checked it lies in the file), or a .gltf's text.
std::string_view json_of(const std::string& data, bool binary) {
  if (!binary) return data;
  uint32_t json_length;
  std::memcpy(&json_length, data.data() + 12, 4);
  return std::string_view(data).substr(20, json_length);
}

// The file without its images and textures (which gpsurf does not use), for a file whose images
// tinygltf cannot decode: a .gltf's JSON, or a .glb with its JSON chunk replaced.
std::string without_images(const std::string& data, bool binary) {
  const std::string_view json_text = json_of(data, binary);
  nlohmann::json json = nlohmann::json::parse(json_text.begin(), json_text.end(), nullptr, false);
  if (!json.is_object()) return data;
  json.erase("images");
  json.erase("textures");
  std::string text = json.dump();
  if (!binary) return text;
  while (text.size() % 4 != 0) text += ' ';
  const size_t rest = 20 + json_text.size();
  std::string out = data.substr(0, 12);
  const uint32_t json_length = uint32_t(text.size()), json_type = 0x4E4F534A;
  const uint32_t total = uint32_t(20 + text.size() + (data.size() - rest));
  std::memcpy(out.data() + 8, &total, 4);
  out.append(reinterpret_cast<const char*>(&json_length), 4).append(reinterpret_cast<const char*>(&json_type), 4);
  return out + text + data.substr(rest);
}

}  // namespace

tinygltf::Model load_gltf_model(const std::string& data, const std::string& base_dir,
                                std::vector<std::string>& warnings) {
  if (data.size() > UINT_MAX) throw Error("is larger than tinygltf reads (4 GiB)");
  const bool binary = data.size() >= 4 && data.compare(0, 4, "glTF") == 0;
  const bool has_bin_chunk = binary && check_glb_chunks(data);
  const GltfHead head = read_gltf_head(json_of(data, binary));
  // A buffer without a uri is a .glb's BIN chunk: a .gltf has none, a .glb may leave the chunk out.
  if (head.buffer_without_uri && !has_bin_chunk)
    throw Error(
        "buffer " + std::to_string(*head.buffer_without_uri) + " has no uri" +
        (binary ? ", and the .glb no BIN chunk to hold it" : " (only a .glb's buffer may go without: its BIN chunk)"));
  // The folder is passed as the callbacks' user data: none means no file is read.
  BufferFolder folder{base_dir, {}};
  for (const std::string& uri : head.buffer_uris)
    if (const std::string asked = uri_form_decoded(uri), named = uri_decoded(uri); asked != named)
      folder.renamed[base_dir + "/" + asked] = base_dir + "/" + named;
  const auto load = [&](const std::string& file, std::string& err, std::string& warn) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    loader.SetFsCallbacks(
        {regular_file_exists, path_named, read_buffer_file, write_nothing, base_dir.empty() ? nullptr : &folder});
    tinygltf::Model model;
    bool loaded = false;
    try {
      loaded =
          binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(file.data()),
                                               unsigned(file.size()), base_dir)
                 : loader.LoadASCIIFromString(&model, &err, &warn, file.data(), unsigned(file.size()), base_dir);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      throw Error(loader_error(e.what()));
    }
    // tinygltf reads a .glb whose JSON chunk is not padded to 4 bytes, but starts its errors with saying so.
    if (const std::string unpadded = "JSON Chunk end does not aligned to a 4-byte boundary."; err.starts_with(unpadded))
      err.erase(0, unpadded.size());
    return loaded ? std::optional(std::move(model)) : std::nullopt;
  };
  std::string err, warn;
  std::optional<tinygltf::Model> model = load(data, err, warn);
  // Images that cannot be decoded do not stop the mesh: it is read again without them.
  const bool images_failed = !model && err.find("for image[") != std::string::npos;
  if (images_failed) {
    std::string again_err, again_warn;
    model = load(without_images(data, binary), again_err, again_warn);
    if (!model) throw Error(loader_error(again_err.empty() ? again_warn : again_err));
  }
  if (!model) throw Error(loader_error(err.empty() ? warn : err));
  // tinygltf warns only of images: each that is not there gives two lines (whose names may hold any byte).
  size_t images = 0;
  for (size_t at = warn.find("for image["); at != std::string::npos; at = warn.find("for image[", at + 1)) ++images;
  if (images > 0 || images_failed)
    warnings.push_back(images_failed
                           ? "its images could not be decoded and were read past (gpsurf does not use textures)"
                           : std::to_string(images) + (images == 1 ? " image is" : " images are") +
                                 " not there or empty, read past (gpsurf does not use textures)");
  return std::move(*model);
}

}  // namespace gps
