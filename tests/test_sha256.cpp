// SHA-256 against the standard's test vectors (FIPS 180-4's examples, as NIST publishes them),
// the padding at every length where it changes shape, the message fed in pieces, and the
// comparison of digests.
#include <catch2/catch.hpp>
#include <string>

#include "hall/sha256.hpp"

using namespace termpool::hall;

TEST_CASE("sha256: the standard's test vectors", "[hall][sha256]") {
    CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    // 448 bits: the padding's 1 bit and length need a second block.
    CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
          "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
    CHECK(sha256_hex("abcdefghbcdefghicdefghijdefghijkefghijklfghijklmghijklmnhijklmnoijklmnopjklm"
                     "nopqklmnopqrlmnopqrsmnopqrstnopqrstu") ==
          "cf5b16a778af8380036ce59e7b0492370b249b11e8f07a51afac45037afee9d1");
    CHECK(sha256_hex(std::string(1'000'000, 'a')) ==
          "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("sha256: the padding at the lengths where it changes, and the digest's bytes",
          "[hall][sha256]") {
    // 55 bytes leave room for the 1 bit and the length in one block, 56 do not; 64 fill one.
    // (Reference digests from Python's hashlib.)
    CHECK(sha256_hex(std::string(55, 'a')) ==
          "9f4390f8d30c2dd92ec9f095b65e2b9ae9b0a925a5258e241c9f1e910f734318");
    CHECK(sha256_hex(std::string(56, 'a')) ==
          "b35439a4ac6f0948b6d6f9e3c6af0f5f590ce20f1bde7090ef7970686ec6738a");
    CHECK(sha256_hex(std::string(63, 'a')) ==
          "7d3e74a05d7db15bce4ad9ec0658ea98e3f06eeecf16b4c6fff2da457ddc2f34");
    CHECK(sha256_hex(std::string(64, 'a')) ==
          "ffe054fe7ae0cb6dc65c3af9b61d5209f439851db43d0ba5997337df154668eb");
    CHECK(sha256_hex(std::string(119, 'a')) ==
          "31eba51c313a5c08226adf18d4a359cfdfd8d2e816b13f4af952f7ea6584dcfb");
    CHECK(sha256_hex(std::string(120, 'a')) ==
          "2f3d335432c70b580af0e8e1b3674a7c020d683aa5f73aaaedfdc55af904c21c");
    // Every byte value, high bit set or not, counts as unsigned.
    std::string bytes;
    for (int b = 0; b < 256; ++b)
        bytes += static_cast<char>(b);
    CHECK(sha256_hex(bytes) == "40aff2e9d2d8922e47afd4648e6967497158785fbd1da870e7110266bf944880");
    const Sha256Digest abc = sha256("abc");
    CHECK(abc.front() == 0xba);
    CHECK(abc.back() == 0xad);
}

TEST_CASE("sha256: a message fed in pieces hashes as the whole", "[hall][sha256]") {
    std::string message;
    for (int i = 0; i < 300; ++i)
        message += static_cast<char>('!' + i % 90);
    const Sha256Digest whole = sha256(message);
    Sha256 pieces;
    for (std::size_t cut = 0; cut <= message.size(); cut += 7) {
        INFO("cut at " << cut);
        pieces.reset();
        pieces.update(std::string_view(message).substr(0, cut));
        pieces.update("");
        pieces.update(std::string_view(message).substr(cut));
        CHECK(pieces.finish() == whole);
    }
    // A reset starts a new message.
    pieces.reset();
    pieces.update("abc");
    CHECK(pieces.finish() == sha256("abc"));
}

TEST_CASE("same_digest: equal text only, whatever byte differs", "[hall][sha256]") {
    const std::string a = sha256_hex("seat token");
    CHECK(same_digest(a, a));
    CHECK(same_digest(a, std::string(a)));
    CHECK(same_digest("", ""));
    for (std::size_t i = 0; i < a.size(); ++i) {
        std::string b = a;
        b[i] = b[i] == '0' ? '1' : '0';
        INFO("byte " << i);
        CHECK_FALSE(same_digest(a, b));
    }
    CHECK_FALSE(same_digest(a, a.substr(0, 63)));
    CHECK_FALSE(same_digest(a, a + "0"));
    CHECK_FALSE(same_digest("", a));
}
