#pragma once
// Catch2 v3 under v2's header name, for a system that ships only v3 (the Makefile puts
// tests/catch3 on the include path then, and links Catch2's own main): the tests are written
// for Debian 12's v2, and use of v3 is limited to what differs between the two.

#include <catch2/catch_all.hpp>

#include <string>

namespace Catch {
/// v2's substring matcher.
inline Matchers::StringContainsMatcher Contains(const std::string& text) {
    return Matchers::ContainsSubstring(text);
}
using Matchers::EndsWith;
using Matchers::StartsWith;
} // namespace Catch

using Catch::Approx;
