#include "interpreter/macro/value.hpp"

#include <cmath>

namespace kerf::interpreter::macro {

// [M-16i] ROUND "rounds off at the first decimal place" (ROUND[1.2345] = 1.0): half away from
// zero, which std::round implements exactly for every double.
double round_half_away(double x) { return std::round(x); }

std::optional<std::int64_t> round_to_integer(double x, std::int64_t min, std::int64_t max) {
    if (!std::isfinite(x)) return std::nullopt;
    const double r = round_half_away(x);
    if (r < static_cast<double>(min) || r > static_cast<double>(max)) return std::nullopt;
    return static_cast<std::int64_t>(r);
}

}  // namespace kerf::interpreter::macro
