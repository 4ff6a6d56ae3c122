// gpsurf diff A B -o OUT.png: difference images of position or normal AOVs (thesis Figs. 4.4, 4.8).
#include <cstdio>

#include "app/cli_checks.h"
#include "app/commands.h"
#include "app/gl_commands.h"
#include "core/support/error.h"
#include "render/image/difference_image.h"

namespace gps {

void add_diff_command(CLI::App& app) {
  struct Args {
    std::string a, b, output, kind = "auto";
    double factor = 0, threshold = 1e-3;
  };
  auto args = std::make_shared<Args>();
  auto* cmd = app.add_subcommand("diff", gl_command_summary("diff"));
  cmd->add_option("a", args->a, "first AOV image (.exr)")->required();
  cmd->add_option("b", args->b, "second AOV image (.exr)")->required();
  cmd->add_option("-o,--output", args->output, "difference image (.png)")->required();
  cmd->add_option("--kind", args->kind, "what the AOVs hold (auto: from the channel names render --aov writes)")
      ->check(CLI::IsMember({"auto", "position", "normal"}));
  cmd->add_option("--factor", args->factor, "scale of the shown difference (default 200 for position, 5000 for normal)")
      ->check(positive_number());
  cmd->add_option("--threshold", args->threshold, "count pixels whose difference exceeds this (unscaled)")
      ->check(non_negative_number());
  cmd->callback([args] {
    const Image a = read_image(args->a), b = read_image(args->b);
    if (args->kind == "auto") {
      const auto kind_of = [](const std::string& path) {
        const auto names = read_channel_names(path);
        return names == kNormalChannels ? "normal" : names == kPositionChannels ? "position" : "";
      };
      const std::string ka = kind_of(args->a), kb = kind_of(args->b);
      if (!ka.empty() && !kb.empty() && ka != kb)
        throw usage_error(args->a + " holds " + ka + "s but " + args->b + " holds " + kb + "s");
      // An image that is no AOV of gpsurf render (a colour image, say) tells no kind: say which.
      for (const auto& [path, kind] : {std::pair{args->a, ka}, std::pair{args->b, kb}})
        if (kind.empty())
          throw usage_error(path +
                            " is not a position or normal AOV of gpsurf render (--aov); give --kind to compare "
                            "it as one");
      args->kind = ka;
    }
    const AovKind kind = args->kind == "normal" ? AovKind::normal : AovKind::position;
    const double factor = args->factor > 0 ? args->factor : (kind == AovKind::normal ? 5000.0 : 200.0);
    DifferenceStats s;
    const Image d = difference_image(a, b, kind, factor, args->threshold, s);
    write_image(args->output, d);
    std::printf(
        "%s difference (%s): max %.3g, mean %.3g, %.2f%% of %d pixels above %.3g, %d pixels covered in one image only; "
        "wrote %s\n",
        args->kind.c_str(), kind == AovKind::position ? "distance / bounding-box diagonal" : "largest component", s.max,
        s.mean, 100.0 * s.share_above, s.covered, args->threshold, s.coverage_mismatch, args->output.c_str());
  });
}

}  // namespace gps
