// drive_kernel (drive.hpp) compiled for one species with the viscoelastic normal and asperity
// tangential contact (tables or direct integration).
#include "drive_impl.hpp"

namespace roughgas::detail {

ROUGHGAS_DRIVE_KERNEL(Brilliantov, false);
ROUGHGAS_DRIVE_KERNEL(BrilliantovDirect, false);

} // namespace roughgas::detail
