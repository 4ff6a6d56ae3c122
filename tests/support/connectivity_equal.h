#pragma once
// Two MeshConnectivity values compared field by field (the refined-connectivity tests).
#include <gtest/gtest.h>

#include "core/mesh/mesh_connectivity.h"

namespace gps::test {

inline void expect_equal(const MeshConnectivity& a, const MeshConnectivity& b) {
  EXPECT_EQ(a.edge_verts, b.edge_verts);
  EXPECT_EQ(a.edge_faces, b.edge_faces);
  EXPECT_EQ(a.face_edges, b.face_edges);
  EXPECT_EQ(a.vertex_edge_offsets, b.vertex_edge_offsets);
  EXPECT_EQ(a.vertex_edges, b.vertex_edges);
  EXPECT_EQ(a.vertex_face_offsets, b.vertex_face_offsets);
  EXPECT_EQ(a.vertex_faces, b.vertex_faces);
  EXPECT_EQ(a.vertex_face_corners, b.vertex_face_corners);
}

}  // namespace gps::test
