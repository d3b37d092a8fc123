#pragma once
// The lines of a command's output, for tests that look at them one by one.

#include <sstream>
#include <string>
#include <vector>

namespace termpool::test {

/// The lines of `text`, without their newlines.
inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

} // namespace termpool::test
