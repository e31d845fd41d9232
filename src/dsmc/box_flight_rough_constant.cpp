// run_box (box_flight.hpp) compiled for RoughConstant.
#include "box_flight.hpp"

namespace roughgas::detail {

ROUGHGAS_BOX_FLIGHT(RoughConstant);

} // namespace roughgas::detail
