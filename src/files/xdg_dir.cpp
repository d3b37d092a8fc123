#include "files/xdg_dir.hpp"

#include <cstdlib>

namespace termpool {

std::string xdg_dir(const char* variable, std::string_view under_home) {
    if (const char* dir = std::getenv(variable); dir && *dir)
        return dir;
    const char* home = std::getenv("HOME");
    return std::string(home && *home ? home : ".") + "/" + std::string(under_home);
}

} // namespace termpool
