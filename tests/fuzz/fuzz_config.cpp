// libFuzzer target: the config file parser.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "player/config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    termpool::GameOptions options;
    std::vector<std::string> warnings;
    termpool::apply_config(std::string_view(reinterpret_cast<const char*>(data), size),
                                options, warnings);
    return 0;
}
