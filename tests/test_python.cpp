// The Python module's own tests (tests/python, pytest) against the module this build made:
// the same shots as `termpool simulate` to the bit, the same error messages, sampled motion,
// the referees and a match the computer plays through. A missing Python, pytest or module
// fails here with what to install; it is never skipped.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "tmux_session.hpp"

using tmux_session::require_tool;
using tmux_session::run_with_status;
using tmux_session::shell_quote;

TEST_CASE("the Python module passes its tests", "[e2e][python]") {
    const char* python_env = std::getenv("TERMPOOL_PYTHON");
    const char* module_path = std::getenv("TERMPOOL_PYTHON_PATH");
    INFO("TERMPOOL_PYTHON_PATH names the folder of the module `make python` builds; run these "
         "tests with make test");
    REQUIRE(module_path != nullptr);
    const std::string python = python_env && *python_env ? python_env : "python3";
    require_tool(python, "python3");
    const auto pytest = run_with_status(python + " -c 'import pytest, numpy' 2>&1");
    INFO(pytest.second << "\ninstall python3-pytest and python3-numpy (make deps)");
    REQUIRE(pytest.first == 0);
    // A sanitized module runs in a Python that is not: its runtime is preloaded, and the leak
    // check is left to the C++ tests (the interpreter keeps its own memory to the end).
    const char* preload = std::getenv("TERMPOOL_PRELOAD");
    const std::string sanitizers =
        preload && *preload ? "LD_PRELOAD=" + shell_quote(preload) + " ASAN_OPTIONS=detect_leaks=0 "
                            : "";
    const auto result =
        run_with_status(sanitizers + "PYTHONPATH=" + shell_quote(module_path) + " " + python +
                        " -m pytest -q -p no:cacheprovider tests/python 2>&1");
    INFO(result.second);
    CHECK(result.first == 0);
    CHECK(result.second.find(" passed") != std::string::npos);
}
