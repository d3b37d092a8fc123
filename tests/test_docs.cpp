// The man page is valid, and the install and uninstall targets do what they say.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace {

bool exists(const std::string& path) {
    struct stat st {};
    return stat(path.c_str(), &st) == 0;
}

} // namespace

TEST_CASE("the man page formats without a warning", "[docs]") {
    if (std::system("command -v groff >/dev/null 2>&1") != 0) {
        WARN("groff is missing: the man page check is skipped");
        return;
    }
    CHECK(std::system("test -z \"$(groff -man -ww -z man/termpool.6 2>&1)\"") == 0);
}

TEST_CASE("make install and make uninstall honour DESTDIR and PREFIX", "[docs]") {
    char dir_template[] = "/tmp/termpool-install-XXXXXX";
    const std::string dir = mkdtemp(dir_template);
    // The tests of `make check` use the sanitized tree; install from the tree under test.
    const char* bin = std::getenv("TERMPOOL_BIN");
    const std::string tree =
        bin && std::string(bin).find("/san/") != std::string::npos ? " SANITIZE=1" : "";
    const std::string make =
        "make --no-print-directory -s" + tree + " DESTDIR=" + dir + " PREFIX=/usr ";
    REQUIRE(std::system((make + "install >/dev/null").c_str()) == 0);
    CHECK(exists(dir + "/usr/bin/termpool"));
    CHECK(exists(dir + "/usr/share/man/man6/termpool.6"));
    CHECK(std::system((dir + "/usr/bin/termpool --version >/dev/null").c_str()) == 0);
    REQUIRE(std::system((make + "uninstall >/dev/null").c_str()) == 0);
    CHECK_FALSE(exists(dir + "/usr/bin/termpool"));
    CHECK_FALSE(exists(dir + "/usr/share/man/man6/termpool.6"));
    std::system(("rm -rf " + dir).c_str());
}
