#pragma once
// Where the XDG base directory specification puts a kind of file.

#include <string>
#include <string_view>

namespace termpool {

/// $`variable` when it is set and not empty, else $HOME/`under_home` (. when HOME is unset),
/// e.g. xdg_dir("XDG_CONFIG_HOME", ".config").
std::string xdg_dir(const char* variable, std::string_view under_home);

} // namespace termpool
