#pragma once
/// \file number_format.h
/// \brief Numbers as a physicist prints them: a value with an uncertainty rounded to it (the
/// error to two significant digits when they start with 1 or 2, else one; the value to the
/// same decimal place), and values without an error to a few significant digits. For tables
/// read by people (index.html, `campaign status`); the CSV and Markdown exports keep full
/// precision.
#include <string>

namespace beverloo {

/// "3.3 ± 0.4", "1.27 ± 0.23", "0.005 ± 0.006", "120 ± 50"; a non-finite or zero error gives
/// the value alone (format_value). pm: the separator (" ± " or " &plusmn; ").
std::string format_with_error(double value, double error, const std::string& pm = " ± ");
/// Three significant digits; "inf", "-inf", "nan" spelled out.
std::string format_value(double value, int digits = 3);

}  // namespace beverloo
