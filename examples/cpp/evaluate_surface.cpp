// Reads a covariance mesh (or takes the built-in cone), plans its GPS limit surface, evaluates the
// centre of every patch exactly and writes a tessellation of the whole surface.
#include <cstdio>
#include <exception>
#include <string>

#include "core/evaluation/patch_eval.h"
#include "core/evaluation/tessellator.h"
#include "core/io/mesh_io.h"
#include "core/modelling/samples.h"
#include "core/plans/planned_surface.h"
#include "core/support/freed_memory.h"
#include "core/version.h"

int main(int argc, char** argv) {
  gps::keep_freed_memory();  // large meshes allocate and free large blocks: kept for reuse, not mapped afresh
  try {
    const gps::CovarianceMesh mesh = argc > 1 ? gps::read_mesh(argv[1]) : gps::make_sample("cone-pointy");
    const std::string output = argc > 2 ? argv[2] : "tessellation.obj";
    const gps::PlannedSurface surface(mesh, gps::PlanOptions{});
    const gps::PatchPlans& plans = surface.tables().plans;
    std::printf("gpsurf %s: %zu vertices, %zu faces, %s, %d patches\n", gps::kVersion, mesh.n_vertices(),
                mesh.n_faces(), surface.scheme() == gps::Scheme::loop ? "Loop" : "Catmull-Clark", plans.n_patches());
    // The middle of each patch's domain: (1/2, 1/2) on a quad, (1/3, 1/3) on a triangle.
    const double centre = plans.shape == gps::PatchShape::quad ? 0.5 : 1.0 / 3.0;
    for (int patch = 0; patch < plans.n_patches(); ++patch) {
      const auto sample = gps::evaluate_patch(plans, surface.points(), patch, centre, centre);
      if (!sample) continue;
      const gps::Vec3& p = sample->position;
      const gps::Vec3& n = sample->normal;
      std::printf("patch %d: position (%.9f, %.9f, %.9f) normal (%.6f, %.6f, %.6f)\n", patch, p.x(), p.y(), p.z(),
                  n.x(), n.y(), n.z());
    }
    const gps::TriangleMesh triangles = gps::tessellate(plans, surface.points(), 8);
    gps::write_triangle_mesh(output, triangles);
    std::printf("wrote %s (%zu vertices, %zu triangles)\n", output.c_str(), triangles.positions.size(),
                triangles.triangles.size());
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "evaluate_surface: %s\n", e.what());
    return 1;
  }
}
