// What the editor's repair prompt offers (ui/panels/repair_prompt.h): a mesh the repair mends is offered,
// one it cannot make open (a Möbius strip, which no flipping orients) is not.
#include "ui/panels/repair_prompt.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "tests/support/pinched_mesh.h"
#include "tests/support/temp_dir.h"

namespace gps {
namespace {

// Six quads around a band whose cross-section turns half a turn, the last joining the first backwards.
std::string mobius_obj() {
  constexpr int n = 6;
  std::ostringstream obj;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * i / n, c = std::cos(a), s = std::sin(a);
    const double across_radial = std::cos(a / 2), across_z = std::sin(a / 2);
    obj << "v " << 3 * c + across_radial * c << " " << 3 * s + across_radial * s << " " << across_z << "\n";
    obj << "v " << 3 * c - across_radial * c << " " << 3 * s - across_radial * s << " " << -across_z << "\n";
  }
  for (int i = 0; i + 1 < n; ++i)
    obj << "f " << 2 * i + 1 << " " << 2 * i + 3 << " " << 2 * i + 4 << " " << 2 * i + 2 << "\n";
  obj << "f " << 2 * n - 1 << " 2 1 " << 2 * n << "\n";
  return obj.str();
}

TEST(RepairFindings, RepairIsOfferedOnlyForWhatItMends) {
  test::TempDir dir;
  const RepairFindings pinched = repair_findings(dir.write("pinched.obj", test::kPinchedObj));
  ASSERT_EQ(pinched.refused.size(), 1u);
  EXPECT_NE(pinched.refused[0].find("pinch"), std::string::npos) << pinched.refused[0];
  EXPECT_TRUE(pinched.offered());
  EXPECT_FALSE(repair_findings(dir.write("mobius.obj", mobius_obj())).offered());
  // A file no repair reads, and one that reads as it is: nothing offered.
  EXPECT_FALSE(
      repair_findings(dir.write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nend_header\n")).offered());
  EXPECT_FALSE(repair_findings(dir.write("clean.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")).offered());
}

// Every class the repair mends is listed, the refused one (the pinch) first, elements numbered as the
// OBJ file numbers them (from 1, with their lines).
TEST(RepairFindings, EveryClassTheRepairMendsIsListed) {
  test::TempDir dir;
  const RepairFindings scan = repair_findings(dir.write("scan.obj", test::pinched_scan_obj()));
  EXPECT_EQ(scan.refused, std::vector<std::string>{"non-manifold (pinch) vertices: 1 (vertex 1 (line 1) with 2 fans)"});
  ASSERT_EQ(scan.others.size(), 2u);
  EXPECT_EQ(scan.others[0].rfind("coincident vertices: 26 (vertex 10 (line 10) at vertex 2 (line 2); ", 0), 0u)
      << scan.others[0];
  EXPECT_EQ(scan.others[1].rfind("zero-area faces: 9 (face 11 (line 47); ", 0), 0u) << scan.others[1];
}

}  // namespace
}  // namespace gps
