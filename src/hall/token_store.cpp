#include "hall/token_store.hpp"

#include <algorithm>
#include <string_view>
#include <termpool/record.hpp>

#include "files/atomic_file.hpp"
#include "files/file_limits.hpp"
#include "files/read_file.hpp"
#include "files/xdg_dir.hpp"
#include "hall/protocol.hpp"

namespace termpool::hall {
namespace {

// The longest name's file name must fit any file system's 255 bytes.
static_assert(2 * max_player_name_bytes + std::string_view(".token").size() <= 255);

bool valid_token(std::string_view text) {
    return text.size() == token_hex_digits && std::all_of(text.begin(), text.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

std::string hex_of(std::string_view bytes) {
    static const char digits[] = "0123456789abcdef";
    std::string hex;
    for (const char c : bytes) {
        const auto b = static_cast<unsigned char>(c);
        hex += digits[b >> 4];
        hex += digits[b & 15];
    }
    return hex;
}

} // namespace

std::string default_token_dir() {
    return xdg_dir("XDG_STATE_HOME", ".local/state") + "/termpool/hall-tokens";
}

std::string token_path(const std::string& dir, const std::string& name) {
    return dir + "/" + hex_of(name) + ".token";
}

std::string load_token(const std::string& dir, const std::string& name) {
    if (!valid_player_name(name))
        return {};
    std::string ignored;
    // Only this program writes the folder: a link there is refused, not read through.
    const auto text =
        read_whole_file(token_path(dir, name), ignored, max_token_bytes, Links::no_follow);
    if (!text)
        return {};
    std::string_view token = *text;
    if (token.ends_with('\n'))
        token.remove_suffix(1);
    return valid_token(token) ? std::string(token) : std::string();
}

std::string save_token(const std::string& dir, const std::string& name, const std::string& token) {
    if (!valid_player_name(name))
        return "not a player name: no token kept for it";
    if (!valid_token(token))
        return "not a seat token (" + std::to_string(token_hex_digits) +
               " lowercase hex digits): not kept";
    std::string error;
    write_atomically(token_path(dir, name), token + "\n", error);
    return error;
}

} // namespace termpool::hall
