#pragma once
// The player's defaults: $XDG_CONFIG_HOME/termpool/config (default ~/.config/termpool/config),
// one `key = value` per line, `#` comments. The command line overrides it.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "player/options.hpp"

namespace termpool {

/// The path of the config file.
std::string config_path();

/// Applies the config text to `options`. Returns an error "LINE: what is wrong" for a bad
/// value; unknown keys only add a warning naming them.
std::optional<std::string> apply_config(std::string_view text, GameOptions& options,
                                        std::vector<std::string>& warnings);

} // namespace termpool
