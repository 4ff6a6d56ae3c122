// libFuzzer entry point for one file reader (chosen at build time, fuzz/CMakeLists.txt): parse the
// bytes as the reader's format and, when they parse, infer covariances and write the mesh back and
// read it again, as `gpsurf infer` would. A reader may refuse input only with gps::Error.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/io/gltf_io.h"
#include "core/io/mesh_import.h"
#include "core/io/ply_io.h"

namespace {
gps::CovarianceMesh parse(const std::string& data) {
#if defined(GPS_FUZZ_READER_ply)
  return gps::parse_ply(data, "fuzz.ply").mesh;
#elif defined(GPS_FUZZ_READER_obj)
  return gps::parse_obj(data, "fuzz.obj");
#elif defined(GPS_FUZZ_READER_off)
  return gps::parse_off(data, "fuzz.off");
#elif defined(GPS_FUZZ_READER_gltf)
  bool has_covariances = false;  // no folder: a buffer file named in the input is never read
  return gps::mesh_of_soup(gps::parse_gltf_soup(data, "fuzz.glb", "", has_covariances), "fuzz.glb");
#else
  return gps::parse_stl(data, "fuzz.stl");
#endif
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* bytes, size_t size) {
  const std::string data(reinterpret_cast<const char*>(bytes), size);
  gps::CovarianceMesh mesh;
  try {
    mesh = parse(data);
    if (mesh.n_faces() > 0) gps::infer_covariances(mesh, 0.05);
    gps::validate_gaussians(mesh, "fuzz");
  } catch (const gps::Error&) {
    return 0;
  }
  // What passes validation writes and reads back without an error.
  std::ostringstream out;
  gps::write_ply(out, mesh, size % 2 == 0);
  gps::parse_ply(out.str(), "round-trip.ply");
  return 0;
}
