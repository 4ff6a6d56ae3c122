#pragma once
// Bridging: joining two boundary loops (or two open boundary chains), or the borders of two face
// regions, with a band of quads, and triangles where one is longer than the other.
//
// Like every modelling operation (core/modelling/mesh_arrays.h) these take a mesh and return a new
// one with a selection and a one-line summary, never changing their input; on refusal they throw
// gps::Error with a one-line reason and nothing is changed. The band's faces are appended; no vertex
// is added or moved. On a mesh of triangles the band's quads are split along their shorter diagonal,
// so that the mesh stays one (and Loop's).
#include <vector>

#include "core/modelling/mesh_arrays.h"

namespace gps {

/// Joins two boundary loops, each given as its vertices in any rotation and either direction and
/// forming a whole boundary loop, or two open boundary chains (consecutive vertices joined by
/// boundary edges), with a band. The two run opposite ways along their faces' edges, which keeps the
/// orientation consistent. Of n ≥ m vertices, the band has m quads (m − 1 for chains) and n − m
/// triangles fanning from the shorter run, spread evenly along it (as Blender does); chains pair
/// their ends, and loops take the start and spread of the triangles that minimise the total length
/// of the band's edges between the loops. Refuses vertices not on a boundary, vertices in both, a
/// loop with a chain, an edge the band would give a third face (the loops already joined by it), a
/// face of no area (the loops coincide there) and a result that is not manifold. Selection: both
/// loops' vertices.
Modelled bridge(const CovarianceMesh& mesh, const std::vector<int>& loop_a, const std::vector<int>& loop_b);

/// Deletes two face regions (faces joined by edges; a single face is one) and bridges the boundary
/// loops they leave, as above; vertices inside a region go with its faces, the rest keep their order.
/// Where both regions' borders are loops of the mesh's boundary (two faces apart, an open shell's
/// caps), as in Blender the borders are bridged first and the regions then deleted: the band is left.
/// Refuses faces that make other than two regions, a region whose border is not one loop of edges
/// (all between it and other faces, or all on the boundary for both), and regions that touch.
/// Selection: both loops' vertices.
Modelled bridge_faces(const CovarianceMesh& mesh, const std::vector<int>& faces);

/// The editor's bridge: the selected vertices, split by the boundary edges between them into exactly
/// two boundary loops (or two chains), bridged as above; a selection with vertices off the boundary
/// bridges the faces within it (bridge_faces).
Modelled bridge_selected(const CovarianceMesh& mesh, const std::vector<int>& vertices);

}  // namespace gps
