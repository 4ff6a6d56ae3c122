// What the editor's repair prompt offers (ui/repair_prompt.h): a mesh the repair mends is offered,
// one it cannot make open (a Möbius strip, which no flipping orients) is not.
#include "ui/repair_prompt.h"

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
  EXPECT_TRUE(repair_findings(dir.write("mobius.obj", mobius_obj())).refused.empty());
}

}  // namespace
}  // namespace gps
