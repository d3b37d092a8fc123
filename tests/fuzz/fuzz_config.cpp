// libFuzzer target: the config file parser.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tui/config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    termpool::tui::GameOptions options;
    std::vector<std::string> warnings;
    termpool::tui::apply_config(std::string_view(reinterpret_cast<const char*>(data), size),
                                options, warnings);
    return 0;
}
