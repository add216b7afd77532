#pragma once
// Input checks shared by every layer. Each throws InvalidArgument naming the
// parameter, its value and the allowed range; none lets a NaN or an infinity
// through.

#include <string>
#include <string_view>

namespace bounce {

/// Shortest round-trip text of a double ("1e-09", "0.25", "nan", "inf").
std::string format_value(double value);

/// value must be finite.
double require_finite(std::string_view parameter, double value);
/// value must be finite and > 0. `what` names the quantity and unit for the message.
double require_positive(std::string_view parameter, double value, std::string_view what);
/// value must be finite and >= 0.
double require_non_negative(std::string_view parameter, double value, std::string_view what);
/// value must be finite and lo < value < hi.
double require_open_interval(std::string_view parameter, double value, double lo, double hi,
                             std::string_view what);

}  // namespace bounce
