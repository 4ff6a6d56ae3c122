#pragma once
// A small mesh the repair mends: two pyramids sharing their apex (vertex 1, a pinch vertex), as OBJ.
namespace gps::test {

constexpr const char* kPinchedObj =
    "v 0 0 0\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "f 1 3 2\nf 1 4 3\nf 1 5 4\nf 1 2 5\nf 2 3 4 5\n"
    "f 1 6 7\nf 1 7 8\nf 1 8 9\nf 1 9 6\nf 6 9 8 7\n";

}  // namespace gps::test
