// drive_kernel (drive.hpp) compiled for rough spheres with constant restitution (one species and
// same-type mixtures; hard-sphere and Maxwell kernels).
#include "drive_impl.hpp"

namespace roughgas::detail {

ROUGHGAS_DRIVE_KERNEL(RoughConstant, false);
ROUGHGAS_DRIVE_KERNEL(RoughConstant, true);

} // namespace roughgas::detail
