// run_box (box_flight.hpp) compiled for Brilliantov.
#include "box_flight.hpp"

namespace roughgas::detail {

ROUGHGAS_BOX_FLIGHT(Brilliantov);

} // namespace roughgas::detail
