#include "player/save_file.hpp"

#include "files/xdg_dir.hpp"

namespace termpool {

std::string save_dir() {
    return xdg_dir("XDG_STATE_HOME", ".local/state") + "/termpool";
}

} // namespace termpool
