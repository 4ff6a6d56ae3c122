// gpsurf infer IN -o OUT: covariances for a plain mesh (GPS paper Eq. 16–17, or isotropic), and
// optionally creases where the surface folds (--crease-angle).
#include <iostream>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/mesh_output.h"
#include "app/repair_arguments.h"
#include "core/mesh/crease_by_angle.h"
#include "core/support/error.h"
#include "core/mesh/inference.h"
#include "core/io/mesh_io.h"

namespace gps {

void add_infer_command(CLI::App& app) {
  struct Args {
    std::string input, output;
    double bias = 0.05, isotropic = 0, crease_angle = -1;
    bool ascii = false;
    RepairArguments repair;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("infer", "Infer vertex covariances from the mesh (replaces any in the file)");
  cmd->add_option("input", args->input, "input mesh")->required();
  cmd->add_option("-o,--output", args->output, "output covariance PLY")->required();
  auto* bias = cmd->add_option("--bias", args->bias, "bias added to the face covariances, times λmax (Eq. 16)")
                   ->check(positive_number());
  cmd->add_option("--isotropic", args->isotropic, "isotropic covariances: σ = S × mean edge length")
      ->check(positive_number())
      ->excludes(bias);
  cmd->add_option("--crease-angle", args->crease_angle,
                  "make edges whose faces meet at more than DEGREES (0..180) infinitely sharp, as Blender's "
                  "sharp by angle")
      ->check(number_in(0, 180));
  cmd->add_flag("--ascii", args->ascii, "ASCII PLY (default: binary little endian)");
  add_repair_arguments(cmd, args->repair);
  cmd->callback([args] {
    ImportOptions options;  // a plain mesh gets the same kind of covariances on import
    options.bias = args->bias;
    if (args->isotropic > 0) {
      options.covariance = ImportOptions::Covariance::isotropic;
      options.isotropic_scale = args->isotropic;
    }
    CovarianceMesh m = read_mesh_repairing(args->input, args->repair, options);
    if (args->isotropic > 0)
      isotropic_covariances(m, args->isotropic);
    else
      infer_covariances(m, args->bias);
    if (args->crease_angle >= 0) {
      const int marked = crease_by_angle(m, args->crease_angle);
      std::cout << "creased " << marked << (marked == 1 ? " edge" : " edges") << " folded by more than "
                << args->crease_angle << " degrees (infinitely sharp)\n";
    }
    write_mesh_noting(args->output, m, !args->ascii);
    std::cout << "wrote " << args->output << "\n";
  });
}

}  // namespace gps
