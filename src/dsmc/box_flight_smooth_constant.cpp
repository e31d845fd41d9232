// run_box (box_flight.hpp) compiled for SmoothConstant.
#include "box_flight.hpp"

namespace roughgas::detail {

ROUGHGAS_BOX_FLIGHT(SmoothConstant);

} // namespace roughgas::detail
