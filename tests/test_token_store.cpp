// The client's seat tokens, one file per player name: where they go, that any valid name
// makes a safe file of its own, that the file is private and written whole, and that what does
// not read as a token is no token.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

#include "file_helpers.hpp"
#include "hall/hall_state.hpp"
#include "hall/token_store.hpp"
#include "scoped_env.hpp"
#include "temp_dir.hpp"

using namespace termpool::hall;
using termpool::test::contents;
using termpool::test::mode_of;
using termpool::test::names_in;
using termpool::test::ScopedEnv;
using termpool::test::TempDir;

namespace {

namespace fs = std::filesystem;

} // namespace

TEST_CASE("token store: the default folder follows XDG_STATE_HOME, else HOME", "[hall][tokens]") {
    {
        ScopedEnv state("XDG_STATE_HOME", "/srv/pool/state");
        CHECK(default_token_dir() == "/srv/pool/state/termpool/hall-tokens");
    }
    {
        ScopedEnv state("XDG_STATE_HOME", "");
        ScopedEnv home("HOME", "/home/pool");
        CHECK(default_token_dir() == "/home/pool/.local/state/termpool/hall-tokens");
    }
    {
        ScopedEnv state("XDG_STATE_HOME", std::nullopt);
        ScopedEnv home("HOME", "/home/pool");
        CHECK(default_token_dir() == "/home/pool/.local/state/termpool/hall-tokens");
    }
}

TEST_CASE("token store: a token saved for a name loads back, in a private file of its own",
          "[hall][tokens]") {
    TempDir tmp("termpool-tokens");
    const std::string dir = tmp.path() + "/state/termpool/hall-tokens"; // made by the save
    const std::string ann = new_seat_token(), bob = new_seat_token();
    CHECK(load_token(dir, "Ann") == ""); // nothing saved yet, no folder either
    REQUIRE(save_token(dir, "Ann", ann) == "");
    REQUIRE(save_token(dir, "Bob", bob) == "");
    CHECK(load_token(dir, "Ann") == ann);
    CHECK(load_token(dir, "Bob") == bob);
    CHECK(load_token(dir, "ann") == ""); // names are compared exactly, as the server does
    CHECK(mode_of(tmp.path() + "/state") == 0700);
    CHECK(mode_of(dir) == 0700);
    // The hex of the name's bytes: "Ann" is 41 6e 6e.
    CHECK(token_path(dir, "Ann") == dir + "/416e6e.token");
    CHECK(mode_of(dir + "/416e6e.token") == 0600);
    CHECK(contents(dir + "/416e6e.token") == ann + "\n");

    // A new token replaces the old one; no temporary file stays behind.
    const std::string again = new_seat_token();
    REQUIRE(save_token(dir, "Ann", again) == "");
    CHECK(load_token(dir, "Ann") == again);
    CHECK(mode_of(dir + "/416e6e.token") == 0600);
    CHECK(names_in(dir) == std::vector<std::string>{"416e6e.token", "426f62.token"});
}

TEST_CASE("token store: any valid name is a safe file name of its own", "[hall][tokens]") {
    TempDir tmp("termpool-tokens");
    const std::string dir = tmp.path() + "/tokens";
    const std::vector<std::string> names = {
        "Ann",
        "..",
        "../../etc/passwd",
        ".hidden",
        "a/b",
        "Ann Lee",
        "*?[]$`'\"\\",
        "Zo\xc3\xab \xf0\x9f\x8e\xb1", // "Zoë 🎱"
        std::string(80, 'x'),          // the longest name a seat takes
    };
    std::set<std::string> tokens;
    for (const std::string& name : names) {
        INFO("name '" << name << "'");
        REQUIRE(termpool::valid_player_name(name));
        const std::string token = new_seat_token();
        tokens.insert(token);
        REQUIRE(save_token(dir, name, token) == "");
        CHECK(load_token(dir, name) == token);
        const std::string file = fs::path(token_path(dir, name)).filename().string();
        REQUIRE(file.size() == 2 * name.size() + 6);
        CHECK(file.substr(0, 2 * name.size()).find_first_not_of("0123456789abcdef") ==
              std::string::npos);
        CHECK(file.ends_with(".token"));
        CHECK(fs::path(token_path(dir, name)).parent_path() == dir);
    }
    // Every name got a file of its own in the folder, and nothing went anywhere else.
    const std::vector<std::string> files = names_in(dir);
    CHECK(files.size() == tokens.size());
    CHECK(names_in(tmp.path()) == std::vector<std::string>{"tokens"});
}

TEST_CASE("token store: what is not a token, or not a name, is none", "[hall][tokens]") {
    TempDir tmp("termpool-tokens");
    const std::string dir = tmp.path();
    const std::string token = new_seat_token();
    const std::string file = token_path(dir, "Ann");

    SECTION("a file that does not hold a token loads as none") {
        for (const std::string& text :
             {std::string(), std::string("\n"), token.substr(1) + "\n", token + "0\n",
              std::string(32, 'A') + "\n", token + "\n\n", token + " \n", " " + token,
              std::string(32, 'g'), token + "\n" + token + "\n"}) {
            INFO("file '" << text << "'");
            tmp.write(fs::path(file).filename().string(), text);
            CHECK(load_token(dir, "Ann") == "");
        }
        tmp.write(fs::path(file).filename().string(), token); // no newline: still a token
        CHECK(load_token(dir, "Ann") == token);
    }
    SECTION("a file that cannot be read loads as none") {
        REQUIRE(fs::create_directory(file)); // a folder in its place
        CHECK(load_token(dir, "Ann") == "");
        CHECK_THAT(save_token(dir, "Ann", token), Catch::Contains(file));
    }
    SECTION("an invalid name or token is refused before anything is written") {
        for (const std::string& name :
             {std::string(), std::string(" Ann"), std::string("Ann "), std::string("a\nb"),
              std::string("tab\there"), std::string(81, 'x'), std::string("\xe6\x97")}) {
            INFO("name '" << name << "'");
            CHECK_THAT(save_token(dir, name, token), Catch::Contains("not a player name"));
            CHECK(load_token(dir, name) == "");
        }
        for (const std::string& bad :
             {std::string(), token.substr(2), token + "00", std::string(32, 'F'),
              token.substr(0, 31) + "\n", std::string("../") + token.substr(3)}) {
            INFO("token '" << bad << "'");
            CHECK_THAT(save_token(dir, "Ann", bad), Catch::Contains("not a seat token"));
        }
        CHECK(names_in(dir).empty());
    }
    SECTION("a folder that cannot be made is reported") {
        tmp.write("in-the-way", "a file\n");
        CHECK_THAT(save_token(dir + "/in-the-way/tokens", "Ann", token),
                   Catch::Contains("cannot create the folder"));
    }
}
