#pragma once
// Numbers in text outputs (CSV, JSON, XDMF): the shortest decimal that reads back as the
// same double (std::to_chars), so text files lose no precision.
#include <string>

namespace capsula::io {

/// "0.1", "1e-12", "3", "nan", "inf", "-inf".
std::string shortestDecimal(double value);

/// Parses what shortestDecimal writes (the whole text must be one number). False if it
/// is not one.
bool parseDecimal(const std::string& text, double& value);

} // namespace capsula::io
