#pragma once
// A scratch directory for tests that write files: made under $TMPDIR (or /tmp), removed with
// everything in it.

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace termpool::test {

/// A directory under $TMPDIR (or /tmp) that is removed with everything in it.
class TempDir {
public:
    /// A new directory named `stem`-XXXXXX.
    explicit TempDir(const std::string& stem = "termpool") {
        const char* base = std::getenv("TMPDIR");
        std::string pattern = std::string(base && *base ? base : "/tmp") + "/" + stem + "-XXXXXX";
        REQUIRE(mkdtemp(pattern.data()) != nullptr);
        path_ = pattern;
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    /// Writes `text` to a file named `name` in the directory and returns its path.
    std::string write(const std::string& name, const std::string& text) const {
        const std::string file = path_ + "/" + name;
        std::ofstream(file, std::ios::binary) << text;
        return file;
    }
    /// The directory.
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

} // namespace termpool::test
