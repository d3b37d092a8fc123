#include "hall/token.hpp"

#include <cstdint>
#include <fstream>
#include <random>

namespace termpool::hall {

namespace {

std::string hex(const unsigned char* bytes, std::size_t count) {
    static constexpr char digits[] = "0123456789abcdef";
    std::string out;
    for (std::size_t i = 0; i < count; ++i) {
        out += digits[bytes[i] >> 4];
        out += digits[bytes[i] & 0xf];
    }
    return out;
}

} // namespace

std::string new_token() {
    unsigned char bytes[16] = {};
    std::ifstream urandom("/dev/urandom", std::ios::binary);
    if (!urandom.read(reinterpret_cast<char*>(bytes), sizeof bytes)) {
        std::random_device device;
        for (unsigned char& b : bytes)
            b = static_cast<unsigned char>(device());
    }
    return hex(bytes, sizeof bytes);
}

std::string token_hash(std::string_view token) {
    std::uint64_t h = 14695981039346656037ULL;
    for (const char c : token) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ULL;
    }
    unsigned char bytes[8];
    for (int i = 0; i < 8; ++i)
        bytes[i] = static_cast<unsigned char>(h >> (56 - 8 * i));
    return hex(bytes, sizeof bytes);
}

} // namespace termpool::hall
