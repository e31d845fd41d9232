// drive_kernel (drive.hpp) compiled for smooth spheres with constant restitution (one species and
// same-type mixtures; hard-sphere and Maxwell kernels).
#include "drive_impl.hpp"

namespace roughgas::detail {

ROUGHGAS_DRIVE_KERNEL(SmoothConstant, false);
ROUGHGAS_DRIVE_KERNEL(SmoothConstant, true);

} // namespace roughgas::detail
