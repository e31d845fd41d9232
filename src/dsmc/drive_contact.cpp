// drive_kernel (drive.hpp) compiled for one species whose restitution comes from the contact model:
// Coulomb friction, viscoelastic (tables or direct integration).
#include "drive_impl.hpp"

namespace roughgas::detail {

ROUGHGAS_DRIVE_KERNEL(Coulomb, false);
ROUGHGAS_DRIVE_KERNEL(ViscoelasticSmooth, false);
ROUGHGAS_DRIVE_KERNEL(Viscoelastic, false);
ROUGHGAS_DRIVE_KERNEL(ViscoelasticSmoothDirect, false);
ROUGHGAS_DRIVE_KERNEL(ViscoelasticDirect, false);

} // namespace roughgas::detail
