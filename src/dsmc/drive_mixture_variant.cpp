// drive_kernel (drive.hpp) compiled for mixtures whose pairs need different policy types: one
// variant per pair, visited per collision.
#include "drive_impl.hpp"

namespace roughgas::detail {

ROUGHGAS_DRIVE_KERNEL(AnySmoothPolicy, true);
ROUGHGAS_DRIVE_KERNEL(AnyRoughPolicy, true);

} // namespace roughgas::detail
