// run_box (box_flight.hpp) compiled for AnyRoughPolicy.
#include "box_flight.hpp"

namespace roughgas::detail {

ROUGHGAS_BOX_FLIGHT(AnyRoughPolicy);

} // namespace roughgas::detail
