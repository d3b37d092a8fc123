// Names people give: nothing hidden in them and no direction controls, wherever a name is
// taken (the prompts, --player1/--player2, --name, the config, the hall's hello); and the key
// the hall compares them by, after NFKC and case folding.
#include <catch2/catch.hpp>
#include <string>
#include <termpool/name_characters.hpp>
#include <unicode/uchar.h>
#include <vector>

#include "hall/name_key.hpp"
#include "player/config.hpp"
#include "player/options.hpp"
#include "player/player_name.hpp"

using namespace termpool;

TEST_CASE("the hidden characters are Unicode's, as ICU knows them", "[names]") {
    // Default_Ignorable_Code_Point, Cc, Cf, Zl and Zp; written out in the core, which does
    // without ICU, and compared here over every code point.
    int hidden = 0;
    for (char32_t cp = 0; cp <= 0x10FFFF; ++cp) {
        const auto c = static_cast<UChar32>(cp);
        const int type = u_charType(c);
        const bool icu = u_hasBinaryProperty(c, UCHAR_DEFAULT_IGNORABLE_CODE_POINT) ||
                         type == U_CONTROL_CHAR || type == U_FORMAT_CHAR ||
                         type == U_LINE_SEPARATOR || type == U_PARAGRAPH_SEPARATOR;
        if (icu != is_hidden_character(cp) ||
            is_bidi_control(cp) != static_cast<bool>(u_hasBinaryProperty(c, UCHAR_BIDI_CONTROL)))
            FAIL_CHECK("U+" << std::hex << static_cast<unsigned>(cp) << ": ICU " << icu);
        hidden += icu;
    }
    CHECK(hidden > 4000); // the tags and variation selectors are most of them
}

TEST_CASE("a typed name with a hidden or direction character is refused, and says why", "[names]") {
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"Ann\u200B", "a name may not hold U+200B (an invisible character)"},
        {"\u202EnnA", "a name may not hold U+202E (it changes the direction of the text)"},
        {"Bob\u2067", "a name may not hold U+2067 (it changes the direction of the text)"},
        {"Ann\u034F", "a name may not hold U+034F (an invisible character)"},
        {"A\x07nn", "a name may not hold U+0007 (a control character)"},
        {"A\xc2\x9bnn", "a name may not hold U+009B (a control character)"},
        {"A\xffnn", "the name is not valid UTF-8"},
        // Nothing that shows: wide or no-break spaces, marks with nothing to mark.
        {"\u00A0", "a name needs a character that shows"},
        {"\u3000\u2003", "a name needs a character that shows"},
        {"\u0301\u0301", "a name needs a character that shows"},
    };
    for (const auto& [name, why] : bad) {
        INFO(name);
        std::string error;
        CHECK_FALSE(clean_player_name(name, error));
        CHECK(error == why);
        CHECK(name_characters_problem(name) == why);

        std::string option_error;
        CHECK_FALSE(parse_game_options({"--player1", name}, option_error));
        CHECK(option_error == "--player1: " + why);

        GameOptions options;
        std::vector<std::string> warnings;
        CHECK(apply_config("\nplayer2 = " + name + "\n", options, warnings) ==
              "2: player2: " + why);
    }
    // Ten ideographic spaces fill the 20 columns: the letter after them is cut off, and what is
    // left shows nothing.
    std::string cut_error;
    CHECK_FALSE(clean_player_name("\u3000\u3000\u3000\u3000\u3000\u3000\u3000\u3000\u3000\u3000X",
                                  cut_error));
    CHECK(cut_error == "a name needs a character that shows");
    for (const std::string good : {"Ann", "Zoë", "Zoe\u0308", "李小龍", "محمد", "🎱"}) {
        INFO(good);
        std::string error;
        CHECK(clean_player_name(good, error) == good);
        CHECK(error.empty());
    }
}

TEST_CASE("name_key: one key for a name however it is typed", "[names]") {
    using hall::name_key;
    const std::string ann = name_key("Ann");
    CHECK(ann == "ann");
    for (const std::string same :
         {"ANN", "ann", "aNN", "Ａｎｎ", "ＡＮＮ", "Ann\u200B", "A\u00ADnn"}) {
        INFO(same);
        CHECK(name_key(same) == ann);
    }
    // Precomposed and combining, upper and lower case.
    CHECK(name_key("\u00C5sa") == name_key("A\u030Asa"));
    CHECK(name_key("\u00C5sa") == name_key("\u00E5SA"));
    CHECK(name_key("Zo\u00EB") == name_key("ZOE\u0308"));
    // Compatibility forms: a ligature, a circled digit, the German sharp s.
    CHECK(name_key("\uFB01sh") == name_key("FISH"));
    CHECK(name_key("Ann\u2460") == name_key("ann1"));
    CHECK(name_key("Stra\u00DFe") == name_key("STRASSE"));
    // Spaces of any width or kind, at the ends or run together, are one space or none.
    for (const std::string same : {"Ann\u00A0", "\u3000Ann", "Ann\u2003", "\u205FAnn\u202F"})
        CHECK(name_key(same) == ann);
    CHECK(name_key("Ann\u00A0\u2003Lee") == name_key("ann lee"));
    // Different names stay different.
    CHECK(name_key("Ann") != name_key("Anne"));
    CHECK(name_key("Ann") != name_key("Anna"));
    CHECK(name_key("Åsa") != name_key("Asa"));
    CHECK(name_key("李") != name_key("季"));
    // What the protocol would refuse is its own key, and never throws.
    CHECK(name_key("A\xffnn") == "A\xffnn");
    CHECK(name_key("") == "");
    CHECK(name_key("\uFDFA").size() > 18); // the longest expansion NFKC knows
}

TEST_CASE("a name prompt takes keys up to the widest name, and no further", "[names]") {
    CHECK(name_has_room("", "A"));
    CHECK(name_has_room(std::string(19, 'a'), "b"));
    CHECK_FALSE(name_has_room(std::string(20, 'a'), "b"));
    // Wide characters count two columns; spaces at the ends are trimmed, as the name will be.
    CHECK(name_has_room("李小龍李小龍李小龍", "李"));        // 20 columns
    CHECK_FALSE(name_has_room("李小龍李小龍李小龍李", "a")); // 21
    CHECK(name_has_room("   " + std::string(17, 'a'), "b"));
    CHECK(name_has_room(std::string(20, 'a'), " ")); // a space at the end goes with the trim
    // What the prompt stops at is what clean_player_name would keep whole.
    std::string error;
    CHECK(clean_player_name(std::string(20, 'a'), error) == std::string(20, 'a'));
}
