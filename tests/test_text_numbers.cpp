// Numbers as state is written: the shortest text that reads back to the same double.
#include "support/random.hpp"
#include "support/text_numbers.hpp"
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

using namespace termpool;

TEST_CASE("format_double prints the shortest text of a double", "[text-numbers]") {
    CHECK(format_double(0.1) == "0.1");
    CHECK(format_double(1.0 / 3) == "0.3333333333333333");
    CHECK(format_double(2.51394579) == "2.51394579");
    CHECK(format_double(20) == "20");
    CHECK(format_double(-1.5) == "-1.5");
    CHECK(format_double(1e-300) == "1e-300");
    CHECK(format_double(std::numeric_limits<double>::denorm_min()) == "5e-324");
    CHECK(format_double(std::numeric_limits<double>::max()) == "1.7976931348623157e+308");
    CHECK(format_double(-std::numeric_limits<double>::min()) == "-2.2250738585072014e-308");
}

TEST_CASE("format_double writes negative zero as 0, and names the values that are no number",
          "[text-numbers]") {
    CHECK(format_double(-0.0) == "0");
    CHECK(format_double(0.0) == "0");
    CHECK(format_double(std::numeric_limits<double>::infinity()) == "inf");
    CHECK(format_double(-std::numeric_limits<double>::infinity()) == "-inf");
    CHECK(format_double(std::numeric_limits<double>::quiet_NaN()) == "nan");
}

TEST_CASE("every double format_double prints reads back to the same bits", "[text-numbers]") {
    Random rng(13);
    const auto same_back = [](double v) {
        const std::optional<double> back = parse_double(format_double(v));
        return back && std::bit_cast<std::uint64_t>(*back) == std::bit_cast<std::uint64_t>(v);
    };
    for (int k = 0; k < 200000; ++k) {
        // Positions and times as the simulator makes them, and any finite bit pattern.
        const double position = rng.uniform(-0.05, 2.6);
        const double time = rng.uniform(0, 60) * rng.uniform();
        double any = std::bit_cast<double>(rng.next());
        if (!std::isfinite(any))
            any = 1.0;
        INFO(format_double(position) << " " << format_double(time) << " " << format_double(any));
        REQUIRE(same_back(position == 0 ? 1.0 : position));
        REQUIRE(same_back(time == 0 ? 1.0 : time));
        REQUIRE(same_back(any == 0 ? 1.0 : any));
    }
    // Neighbours one ulp apart print differently: 9 digits would not tell them apart.
    const double x = 2.51394579;
    const double next = std::nextafter(x, 3.0);
    CHECK(format_double(x) != format_double(next));
    CHECK(parse_double(format_double(next)) == next);
}

TEST_CASE("the canonical readers take each value only in the one text it is written in",
          "[text-numbers]") {
    CHECK(parse_canonical_integer("0") == 0);
    CHECK(parse_canonical_integer("17") == 17);
    CHECK(parse_canonical_integer("-17") == -17);
    for (const char* other : {"01", "00", "+1", "-0", " 1", "1 ", "", "1e1", "0x1", "--1"}) {
        INFO(other);
        CHECK_FALSE(parse_canonical_integer(other));
        CHECK_FALSE(parse_canonical_uint64(other));
    }
    CHECK(parse_canonical_uint64("18446744073709551615") == 18446744073709551615ULL);
    CHECK_FALSE(parse_canonical_uint64("018446744073709551615"));
    CHECK_FALSE(parse_canonical_uint64("-1"));

    CHECK(parse_canonical_double("0.5") == 0.5);
    CHECK(parse_canonical_double("-1.25") == -1.25);
    CHECK(parse_canonical_double("1e-05") == 1e-05);
    CHECK(parse_canonical_double("0") == 0.0);
    for (const char* other :
         {"+0.5", ".5", "0.50", "5e-1", "-0", "00.5", "1E-05", "1e-5", "0.5 ", "", "1.0", "10e0"}) {
        INFO(other);
        CHECK_FALSE(parse_canonical_double(other));
    }
    // The lenient reader, for text people write (scenarios, the command line), takes them.
    CHECK(parse_double("+0.5") == 0.5);
    CHECK(parse_double("5e-1") == 0.5);
}
