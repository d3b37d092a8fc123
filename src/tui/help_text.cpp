// help_text: the keys and mouse actions of the game, and their pages.

#include "tui/help_text.hpp"

#include <algorithm>

#include <termpool/text_width.hpp>

namespace termpool::tui {

const std::string& help_text() {
    static const std::string text = "Keys\n"
                                    "Left Right        turn the aim 1 degree\n"
                                    "Shift+Left Right  0.1 degree; , . 0.01 degree\n"
                                    "Up Down  k j      more / less power\n"
                                    "Space  Enter      shoot\n"
                                    "[ ]               previous / next target ball\n"
                                    "w a s d           spin: follow, left, draw, right\n"
                                    "W A S D           the same in finer steps\n"
                                    "c                 centre the spin\n"
                                    "e E               raise / lower the cue 5 degrees\n"
                                    "v                 level the cue\n"
                                    "p                 power mode: distance / timed\n"
                                    "g                 aiming aid on / off\n"
                                    "z                 close-up of the contact on / off\n"
                                    "1-6               call a pocket\n"
                                    "0                 call safety (on / off)\n"
                                    "u                 9-ball, 10-ball: push-out after the break\n"
                                    "2-7               snooker: nominate a colour by its value\n"
                                    "                  (2 yellow .. 7 black; again: the aimed)\n"
                                    "C                 snooker: concede the frame (y confirms)\n"
                                    "n                 rename a player (not in the hall)\n"
                                    "x                 skip the animation\n"
                                    "?  l              this help; the shots of this rack or frame\n"
                                    "Tab               the hall: the table's chat\n"
                                    "q                 quit (the hall: leave the table)\n"
                                    "\n"
                                    "Ball in hand\n"
                                    "arrows  j k       move the cue ball\n"
                                    "Space  Enter      place it there\n"
                                    "mouse             the cue ball follows the\n"
                                    "                  pointer; a click places it\n"
                                    "\n"
                                    "Practice (termpool practice)\n"
                                    "m                 pick up a ball: click one, or\n"
                                    "                  Tab [ ] through them; arrows\n"
                                    "                  or the pointer move it, Enter\n"
                                    "                  or a click put it down, Esc ends\n"
                                    "r                 take the last shot again\n"
                                    "t                 a new rack\n"
                                    "\n"
                                    "Match\n"
                                    "Enter             the next rack or frame of a match\n"
                                    "\n"
                                    "Mouse\n"
                                    "move              aim at the pointer\n"
                                    "click, drag       aim there\n"
                                    "drag, release     distance mode: the pointer's\n"
                                    "                  distance sets the power, and\n"
                                    "                  releasing shoots\n"
                                    "click a pocket    call it (while numbered)\n"
                                    "[ shoot ]         click it to shoot\n"
                                    "\n"
                                    "This box\n"
                                    "Space Down PgDn j next page\n"
                                    "Up PgUp k         previous page\n"
                                    "Esc q ? Enter     close";
    return text;
}

std::vector<std::string> box_lines(std::string_view text, int columns) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    while (true) {
        const std::size_t nl = text.find('\n', start);
        const std::string_view line =
            text.substr(start, nl == std::string_view::npos ? nl : nl - start);
        // Lines that fit keep their spacing (the help lines up its columns with spaces).
        if (display_width(line) <= columns)
            lines.emplace_back(line);
        else
            for (std::string& piece : wrap_to_width(line, columns))
                lines.push_back(std::move(piece));
        if (nl == std::string_view::npos)
            return lines;
        start = nl + 1;
    }
}

int help_width(int width) {
    int widest = display_width(help_footer(0, 2, true, 1000));
    for (const std::string& line : box_lines(help_text(), 1000))
        widest = std::max(widest, display_width(line));
    // Border and one space either side.
    return std::max(1, std::min(widest, width - 4));
}

std::vector<std::vector<std::string>> help_pages(int width, int height) {
    const int inner = help_width(width);
    const std::vector<std::string> lines = box_lines(help_text(), inner);
    const int footer_rows =
        static_cast<int>(wrap_to_width(help_footer(0, 2, true, inner), inner).size());
    // Borders, a blank above the footer, and the footer.
    const std::size_t per_page = static_cast<std::size_t>(std::max(1, height - 3 - footer_rows));
    std::vector<std::vector<std::string>> pages;
    std::size_t i = 0;
    while (i < lines.size()) {
        while (i < lines.size() && lines[i].empty())
            ++i; // a page never starts with a blank line
        if (i == lines.size())
            break;
        std::size_t end = std::min(lines.size(), i + per_page);
        // Break at a blank line in the page's second half rather than inside a section.
        if (end < lines.size() && !lines[end].empty())
            for (std::size_t k = end - 1; k > i + per_page / 2; --k)
                if (lines[k].empty()) {
                    end = k;
                    break;
                }
        pages.emplace_back(lines.begin() + static_cast<std::ptrdiff_t>(i),
                           lines.begin() + static_cast<std::ptrdiff_t>(end));
        i = end;
    }
    if (pages.empty())
        pages.emplace_back();
    return pages;
}

int help_page_count(int width, int height) {
    return static_cast<int>(help_pages(width, height).size());
}

std::string help_footer(int page, int pages, bool utf8, int width) {
    if (pages <= 1)
        return "Esc closes";
    const std::string n = std::to_string(page + 1) + "/" + std::to_string(pages);
    const std::string head = "page " + n + (utf8 ? " \u2014 " : " - ");
    const bool last = page + 1 >= pages;
    // The longest that fits on one line.
    const std::string forms[] = {
        head + (last ? "PgUp back, Esc closes" : "Space/PgDn more, Esc closes"),
        head + (last ? "Esc closes" : "Space more, Esc closes"),
        n + (last ? " Esc closes" : " Space more, Esc closes")};
    for (const std::string& form : forms)
        if (display_width(form) <= width)
            return form;
    return forms[2];
}

} // namespace termpool::tui
