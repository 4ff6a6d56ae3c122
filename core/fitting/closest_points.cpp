#include "core/fitting/closest_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include "core/fitting/distance_tree_size.h"
#include "core/fitting/surface_distance.h"
#include "core/support/memory_budget.h"

#include "core/evaluation/patch_eval.h"
#include "core/support/error.h"

namespace gps {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Triangle = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// The parameters (u, v) of a patch's samples at `level`, and its triangles over them.
struct PatchGrid {
  std::vector<std::array<double, 2>> uv;
  std::vector<std::array<int, 3>> triangles;
};

PatchGrid patch_grid(PatchShape shape, int L) {
  PatchGrid g;
  const bool triangle = shape == PatchShape::triangle;
  std::vector<int> index(size_t(L + 1) * size_t(L + 1), -1);
  for (int j = 0; j <= L; ++j)
    for (int i = 0; i <= L && (!triangle || i + j <= L); ++i) {
      index[size_t(i + (L + 1) * j)] = int(g.uv.size());
      g.uv.push_back({double(i) / L, double(j) / L});
    }
  const auto at = [&](int i, int j) { return index[size_t(i + (L + 1) * j)]; };
  for (int j = 0; j < L; ++j)
    for (int i = 0; i < L; ++i) {
      if (triangle && i + j >= L) continue;
      g.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      if (!triangle || i + j + 1 < L) g.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return g;
}

PatchSample sample_at(const PatchPlans& plans, const std::vector<Dual>& points, int patch, double u, double v) {
  auto s = evaluate_patch(plans, points, patch, u, v);
  if (!s) throw Error("patch " + std::to_string(patch) + " left the cone of positive definite matrices");
  return *s;
}

// Barycentric coordinates of `x` (a point of the triangle's plane) in triangle a, b, c.
std::array<double, 3> barycentric(const Vec3& x, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, d = x - a;
  const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2), b1 = e1.dot(d), b2 = e2.dot(d);
  const double det = a11 * a22 - a12 * a12;
  if (!(det > 0)) return {1.0, 0.0, 0.0};
  const double s = (a22 * b1 - a12 * b2) / det, t = (a11 * b2 - a12 * b1) / det;
  return {1.0 - s - t, s, t};
}

}  // namespace

void clamp_to_patch(PatchShape shape, double& u, double& v) {
  u = std::clamp(u, 0.0, 1.0);
  v = std::clamp(v, 0.0, 1.0);
  if (shape == PatchShape::triangle && u + v > 1.0) {
    const double excess = 0.5 * (u + v - 1.0);
    u = std::clamp(u - excess, 0.0, 1.0);
    v = 1.0 - u;
  }
}

std::vector<SurfacePoint> closest_limit_points(const PatchPlans& plans, const std::vector<Dual>& points,
                                               const std::vector<Vec3>& targets, int level, int projection_steps) {
  const PatchGrid grid = patch_grid(plans.shape, level);
  const int n_patches = plans.n_patches();
  const size_t per_patch = grid.uv.size();
  const double n_samples = double(per_patch) * n_patches, n_triangles = double(grid.triangles.size()) * n_patches;
  check_output_size({n_samples, n_triangles, sizeof(Vec3) * n_samples + distance_tree_bytes(n_triangles)},
                    "finding the closest points on " + std::to_string(n_patches) + " patches tessellated at level " +
                        std::to_string(level),
                    "triangles", "fit a coarser mesh");
  std::vector<Vec3> positions(per_patch * size_t(n_patches));
  bool outside_cone = false;
#pragma omp parallel for schedule(dynamic, 16)
  for (int patch = 0; patch < n_patches; ++patch)
    for (size_t k = 0; k < per_patch; ++k) {
      const auto s = evaluate_patch(plans, points, patch, grid.uv[k][0], grid.uv[k][1]);
      if (!s) {
#pragma omp atomic write
        outside_cone = true;
        continue;
      }
      positions[size_t(patch) * per_patch + k] = s->position;
    }
  if (outside_cone) throw Error("the limit surface left the cone of positive definite matrices");
  std::vector<Triangle> triangles;
  triangles.reserve(grid.triangles.size() * size_t(n_patches));
  const auto point = [&](size_t i) { return Kernel::Point_3(positions[i][0], positions[i][1], positions[i][2]); };
  for (int patch = 0; patch < n_patches; ++patch)
    for (const auto& t : grid.triangles) {
      const size_t base = size_t(patch) * per_patch;
      triangles.emplace_back(point(base + size_t(t[0])), point(base + size_t(t[1])), point(base + size_t(t[2])));
    }
  AabbTree tree(triangles.cbegin(), triangles.cend());
  tree.accelerate_distance_queries();
  std::vector<SurfacePoint> out(targets.size());
  if (!targets.empty()) tree.closest_point(Kernel::Point_3(0, 0, 0));  // builds the search tree before the threads
  // The point of triangle t's patch nearest p: its parameters interpolated at the triangle's point
  // nearest p, then Gauss-Newton on |x(u, v) − p|², (JᵀJ) δ = −Jᵀ(x − p) with J = [x_u x_v]; near an
  // extraordinary or crease corner, where the parametrisation degenerates, a step is halved until it
  // comes nearer.
  const auto project = [&](const Vec3& p, size_t t) {
    const int patch = int(t / grid.triangles.size());
    const auto& corners = grid.triangles[t % grid.triangles.size()];
    const size_t base = size_t(patch) * per_patch;
    const Kernel::Point_3 nearest =
        Kernel().construct_projected_point_3_object()(triangles[t], Kernel::Point_3(p[0], p[1], p[2]));
    auto b = barycentric(Vec3(nearest.x(), nearest.y(), nearest.z()), positions[base + size_t(corners[0])],
                         positions[base + size_t(corners[1])], positions[base + size_t(corners[2])]);
    for (double& w : b) w = std::max(w, 0.0);
    const double sum = b[0] + b[1] + b[2];
    SurfacePoint sp;
    sp.patch = patch;
    for (int c = 0; c < 3; ++c) {
      sp.u += b[size_t(c)] / sum * grid.uv[size_t(corners[size_t(c)])][0];
      sp.v += b[size_t(c)] / sum * grid.uv[size_t(corners[size_t(c)])][1];
    }
    clamp_to_patch(plans.shape, sp.u, sp.v);
    PatchSample s = sample_at(plans, points, patch, sp.u, sp.v);
    sp.distance = (s.position - p).norm();
    // Where the parameters do not map linearly onto the triangle (a thin or folded one, at a degenerate
    // corner), a corner of it, a point of the surface, may lie nearer.
    for (const int c : corners)
      if (const double d = (positions[base + size_t(c)] - p).norm(); d < sp.distance) {
        sp.u = grid.uv[size_t(c)][0], sp.v = grid.uv[size_t(c)][1], sp.distance = d;
        s = sample_at(plans, points, patch, sp.u, sp.v);
      }
    for (int step = 0; step < projection_steps; ++step) {
      const Vec3 d = s.position - p;
      Eigen::Matrix2d jtj;
      jtj << s.du.dot(s.du), s.du.dot(s.dv), s.du.dot(s.dv), s.dv.dot(s.dv);
      const Eigen::Vector2d jtd(s.du.dot(d), s.dv.dot(d));
      jtj.diagonal().array() += 1e-12 * jtj.trace();
      if (!(jtj.determinant() > 1e-300)) break;
      const Eigen::Vector2d delta = -jtj.ldlt().solve(jtd);
      bool nearer = false;
      for (double share = 1.0; share >= 1.0 / 16 && !nearer; share *= 0.5) {
        double u = sp.u + share * delta[0], v = sp.v + share * delta[1];
        clamp_to_patch(plans.shape, u, v);
        const PatchSample next = sample_at(plans, points, patch, u, v);
        const double distance = (next.position - p).norm();
        if (!(distance < sp.distance)) continue;
        sp.u = u, sp.v = v, sp.distance = distance, s = next;
        nearer = true;
      }
      if (!nearer) break;
    }
    return sp;
  };
  const double diagonal = bounding_box_diagonal(positions);

  const long n = long(targets.size());
#pragma omp parallel for schedule(dynamic, 256)
  for (long i = 0; i < n; ++i) {
    const Vec3& p = targets[size_t(i)];
    const Kernel::Point_3 q(p[0], p[1], p[2]);
    const auto [foot, id] = tree.closest_point_and_primitive(q);
    SurfacePoint best = project(p, size_t(id - triangles.cbegin()));
    // Twice as far as the tessellation lies: the point may lie on a patch beside it (across a crease,
    // or beyond a corner where the parameters stretch), tried each from its triangle nearest p among
    // those near enough.
    if (best.distance > 2 * std::sqrt(CGAL::squared_distance(q, foot)) + 1e-9 * diagonal) {
      // Its triangle's size on top: p may lie between a chord of the border and the border itself.
      const Triangle& t = *id;
      const double r =
          best.distance + std::sqrt(std::max({CGAL::squared_distance(t[0], t[1]), CGAL::squared_distance(t[1], t[2]),
                                              CGAL::squared_distance(t[2], t[0])}));
      std::vector<Primitive::Id> near;
      tree.all_intersected_primitives(CGAL::Bbox_3(p[0] - r, p[1] - r, p[2] - r, p[0] + r, p[1] + r, p[2] + r),
                                      std::back_inserter(near));
      std::map<int, std::pair<double, size_t>> nearest_of_patch;  // by patch: (squared distance, triangle)
      for (const Primitive::Id& other : near) {
        const size_t t = size_t(other - triangles.cbegin());
        const int patch = int(t / grid.triangles.size());
        if (patch == best.patch) continue;
        const double d2 = CGAL::squared_distance(q, *other);
        auto [it, added] = nearest_of_patch.try_emplace(patch, d2, t);
        if (!added && d2 < it->second.first) it->second = {d2, t};
      }
      for (const auto& [patch, candidate] : nearest_of_patch) {
        const SurfacePoint sp = project(p, candidate.second);
        if (sp.distance < best.distance) best = sp;
      }
    }
    out[size_t(i)] = best;
  }
  return out;
}

}  // namespace gps
