#pragma once
// A mesh as a reader produced it, before it becomes a CovarianceMesh: positions, optional
// covariances and faces as vertex-index lists, with nothing yet checked about the topology.
#include <string>
#include <utility>
#include <vector>

#include "core/mesh/covariance_mesh.h"

#include "core/mesh/linalg.h"
#include "core/mesh/mesh_connectivity.h"

namespace gps {

struct PolygonSoup {
  std::vector<Vec3> positions;
  std::vector<Mat3> covariances;  // one per position, or empty for a plain mesh (inferred later)
  PolygonTopology faces;          // its n_vertices is not kept: positions.size() is the count
};

/// The CovarianceMesh of a soup, its arrays taken over (make_covariance_mesh: throws gps::Error naming
/// `source` and the face or vertex where the topology is not a manifold polygon mesh).
inline CovarianceMesh mesh_of_soup(PolygonSoup&& soup, const std::string& source) {
  return make_covariance_mesh(std::move(soup.positions), std::move(soup.covariances), std::move(soup.faces), source);
}

}  // namespace gps
