#include "interpreter/compensation/position_offset.hpp"

namespace kerf::interpreter::compensation {

std::optional<int> position_offset_factor(std::string_view function) {
    if (function == "position-offset-increase") return 1;
    if (function == "position-offset-decrease") return -1;
    if (function == "position-offset-double-increase") return 2;
    if (function == "position-offset-double-decrease") return -2;
    return std::nullopt;
}

}  // namespace kerf::interpreter::compensation
