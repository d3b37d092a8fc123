#include "support/text_lines.hpp"
#include <catch2/catch.hpp>
#include <string>
#include <vector>

using termpool::split_fields;
using termpool::strip_comment;
using termpool::text_lines;

TEST_CASE("text_lines: numbered lines, CRLF, and a last line without a newline", "[text]") {
    const auto lines = text_lines("first\r\n\nthird line\nlast");
    REQUIRE(lines.size() == 4);
    CHECK(lines[0].number == 1);
    CHECK(lines[0].text == "first");
    CHECK(lines[1].number == 2);
    CHECK(lines[1].text.empty());
    CHECK(lines[2].text == "third line");
    CHECK(lines[3].number == 4);
    CHECK(lines[3].text == "last");
    CHECK(text_lines("").empty());
    CHECK(text_lines("one\n").size() == 1);
}

TEST_CASE("strip_comment and split_fields", "[text]") {
    CHECK(strip_comment("ball 1 0.5 0.6 # the one") == "ball 1 0.5 0.6 ");
    CHECK(strip_comment("# all comment").empty());
    CHECK(strip_comment("no comment") == "no comment");
    const std::vector<std::string_view> fields = split_fields("  strike\t2.5  90 \v0 0\f ");
    CHECK(fields == std::vector<std::string_view>{"strike", "2.5", "90", "0", "0"});
    CHECK(split_fields(" \t ").empty());
    CHECK(split_fields("").empty());
}
