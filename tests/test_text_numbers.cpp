// Numbers as state is written: the shortest text that reads back to the same double.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <termpool/random.hpp>
#include <termpool/text_numbers.hpp>

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
