// run_box (box_flight.hpp) compiled for AnySmoothPolicy.
#include "box_flight.hpp"

namespace roughgas::detail {

ROUGHGAS_BOX_FLIGHT(AnySmoothPolicy);

} // namespace roughgas::detail
