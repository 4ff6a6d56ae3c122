#pragma once
// The arrays of a connectivity let go on this thread, kept for the next one made here from another
// (core/mesh/connectivity_update.h) to write into: sized again no larger than they were, the arrays
// are neither allocated nor cleared, which a mesh of a million faces pays for with tens of megabytes
// written twice.
#include "core/mesh/mesh_connectivity.h"

namespace gps {

/// Keeps `c`'s arrays as this thread's spare where they are larger than the spare held and not past
/// a bound (so that what a thread holds stays bounded); else lets them go.
void keep_spare_connectivity(MeshConnectivity&& c);

/// This thread's spare, taken (empty arrays where none is held). Its arrays keep the sizes and values
/// they had: whoever takes it sizes every array and writes every element.
MeshConnectivity take_spare_connectivity();

}  // namespace gps
