#include "interpreter/compensation/position_offset.hpp"

namespace kerf::interpreter::compensation {

std::optional<int> position_offset_factor(dialects::FunctionId function) {
    const int factor = function.def().position_offset;   // the vocabulary's G45–G48 factors
    return factor != 0 ? std::optional<int>(factor) : std::nullopt;
}

}  // namespace kerf::interpreter::compensation
