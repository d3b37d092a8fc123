// libFuzzer target: the scenario parser of `termpool simulate`.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cli/scenario.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    termpool::cli::parse_scenario(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
