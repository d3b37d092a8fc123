#include "cli/numbers.hpp"

#include <cstdio>

namespace termpool::cli {

std::string format_number(double value) {
    if (value == 0)
        value = 0; // turns -0 into +0
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

} // namespace termpool::cli
