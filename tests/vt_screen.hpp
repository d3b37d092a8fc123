#pragma once
// A terminal screen fed with the bytes a program sends: the part of xterm that curses uses with
// the xterm-256color entry (cursor motion, erasing, scroll regions, colours and bold), so that
// a test can check what a terminal shows after them. Anything else is reported, never guessed.

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace termpool::test {

/// One cell as the terminal holds it.
struct VtCell {
    std::string glyph = " "; ///< UTF-8
    int fg = -1;             ///< colour index, -1 for the terminal's default
    int bg = -1;             ///< colour index, -1 for the terminal's default
    bool bold = false;       ///< SGR 1
    bool reverse = false;    ///< SGR 7
};

/// A screen of `width` x `height` cells with xterm's behaviour for what curses sends.
class VtScreen {
public:
    VtScreen(int width, int height)
        : width_(width), height_(height), bottom_(height - 1),
          cells_(static_cast<std::size_t>(width * height)) {}

    /// Applies `bytes`; false (and `error()` says why) at the first sequence it does not know.
    bool feed(std::string_view bytes) {
        for (const char byte : bytes) {
            if (!error_.empty())
                return false;
            take(static_cast<unsigned char>(byte));
        }
        return error_.empty();
    }
    /// Why the last feed stopped, "" when it did not.
    const std::string& error() const { return error_; }
    /// The cell at column x, row y.
    const VtCell& at(int x, int y) const {
        return cells_[static_cast<std::size_t>(y * width_ + x)];
    }

private:
    enum class State { text, escape, charset, csi };

    void take(unsigned char c) {
        switch (state_) {
        case State::escape:
            return escape(c);
        case State::charset:
            state_ = State::text; // ESC ( B and the like: the character set, not used here
            return;
        case State::csi:
            if (c >= 0x40 && c <= 0x7E) {
                state_ = State::text;
                return csi(static_cast<char>(c));
            }
            sequence_.push_back(static_cast<char>(c));
            return;
        case State::text:
            break;
        }
        if (!utf8_.empty() || c >= 0x80)
            return utf8_byte(c);
        switch (c) {
        case 0x1B:
            state_ = State::escape;
            return;
        case '\r':
            x_ = 0;
            pending_wrap_ = false;
            return;
        case '\n':
            line_feed();
            return;
        case '\b':
            x_ = x_ > 0 ? x_ - 1 : 0;
            pending_wrap_ = false;
            return;
        case '\t':
            x_ = std::min(width_ - 1, (x_ / 8 + 1) * 8);
            pending_wrap_ = false;
            return;
        case 0x07:
            return;
        default:
            break;
        }
        if (c < 0x20 || c == 0x7F) {
            error_ = "control character " + std::to_string(c);
            return;
        }
        put(std::string(1, static_cast<char>(c)));
    }

    void utf8_byte(unsigned char c) {
        if (utf8_.empty()) {
            utf8_need_ = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : c >= 0xC0 ? 2 : 0;
            if (utf8_need_ == 0) {
                error_ = "stray UTF-8 continuation byte";
                return;
            }
        }
        utf8_.push_back(static_cast<char>(c));
        if (static_cast<int>(utf8_.size()) == utf8_need_) {
            put(utf8_);
            utf8_.clear();
        }
    }

    void escape(unsigned char c) {
        state_ = State::text;
        switch (c) {
        case '[':
            state_ = State::csi;
            sequence_.clear();
            return;
        case '(':
        case ')':
            state_ = State::charset;
            return;
        case '=':
        case '>':
            return; // keypad modes
        case '7':
            saved_x_ = x_;
            saved_y_ = y_;
            return;
        case '8':
            x_ = saved_x_;
            y_ = saved_y_;
            pending_wrap_ = false;
            return;
        case 'M':
            reverse_index();
            return;
        case 'D':
            line_feed();
            return;
        case 'E':
            x_ = 0;
            line_feed();
            return;
        default:
            error_ = std::string("ESC ") + static_cast<char>(c);
        }
    }

    // The numeric parameters of the CSI sequence so far; missing ones are 0.
    std::vector<int> parameters(std::string_view text) const {
        std::vector<int> values(1, 0);
        for (const char c : text) {
            if (c == ';')
                values.push_back(0);
            else if (c >= '0' && c <= '9')
                values.back() = values.back() * 10 + (c - '0');
        }
        return values;
    }

    void csi(char final) {
        const bool private_mode =
            !sequence_.empty() && (sequence_[0] == '?' || sequence_[0] == '>');
        const std::vector<int> p = parameters(sequence_);
        const int n = std::max(p[0], 1);
        pending_wrap_ = false;
        switch (final) {
        case 'h':
        case 'l':
            if (!private_mode && p[0] == 4 && final == 'h')
                error_ = "insert mode";
            return; // modes: the alternate screen, cursor keys, insert off, wrap on
        case 't':
            return; // window title stack
        case 'm':
            return sgr(p);
        case 'H':
        case 'f':
            y_ = clamp_row(std::max(p[0], 1) - 1);
            x_ = clamp_col((p.size() > 1 ? std::max(p[1], 1) : 1) - 1);
            return;
        case 'd':
            y_ = clamp_row(n - 1);
            return;
        case 'G':
        case '`':
            x_ = clamp_col(n - 1);
            return;
        case 'A':
            y_ = clamp_row(y_ - n);
            return;
        case 'B':
            y_ = clamp_row(y_ + n);
            return;
        case 'C':
            x_ = clamp_col(x_ + n);
            return;
        case 'D':
            x_ = clamp_col(x_ - n);
            return;
        case 'J':
            return erase_display(p[0]);
        case 'K':
            return erase_line(p[0]);
        case 'X':
            for (int i = 0; i < n && x_ + i < width_; ++i)
                blank(x_ + i, y_);
            return;
        case 'P':
            for (int x = x_; x < width_; ++x) {
                if (x + n < width_)
                    cell(x, y_) = cell(x + n, y_);
                else
                    blank(x, y_);
            }
            return;
        case '@':
            for (int x = width_ - 1; x >= x_; --x) {
                if (x - n >= x_)
                    cell(x, y_) = cell(x - n, y_);
                else
                    blank(x, y_);
            }
            return;
        case 'L':
            for (int i = 0; i < n; ++i)
                scroll_down(y_);
            return;
        case 'M':
            for (int i = 0; i < n; ++i)
                scroll_up(y_);
            return;
        case 'S':
            for (int i = 0; i < n; ++i)
                scroll_up(top_);
            return;
        case 'T':
            for (int i = 0; i < n; ++i)
                scroll_down(top_);
            return;
        case 'r':
            top_ = std::max(p[0], 1) - 1;
            bottom_ = (p.size() > 1 && p[1] > 0 ? p[1] : height_) - 1;
            x_ = y_ = 0;
            return;
        case 'b':
            for (int i = 0; i < n; ++i)
                put(last_glyph_);
            return;
        default:
            error_ = "CSI " + sequence_ + final;
        }
    }

    void sgr(const std::vector<int>& p) {
        for (std::size_t i = 0; i < p.size(); ++i) {
            const int v = p[i];
            if (v == 0) {
                pen_ = VtCell{};
            } else if (v == 1) {
                pen_.bold = true;
            } else if (v == 22) {
                pen_.bold = false;
            } else if (v == 7) {
                pen_.reverse = true;
            } else if (v == 27) {
                pen_.reverse = false;
            } else if (v >= 30 && v <= 37) {
                pen_.fg = v - 30;
            } else if (v >= 90 && v <= 97) {
                pen_.fg = v - 90 + 8;
            } else if (v == 39) {
                pen_.fg = -1;
            } else if (v >= 40 && v <= 47) {
                pen_.bg = v - 40;
            } else if (v >= 100 && v <= 107) {
                pen_.bg = v - 100 + 8;
            } else if (v == 49) {
                pen_.bg = -1;
            } else if ((v == 38 || v == 48) && i + 2 < p.size() && p[i + 1] == 5) {
                (v == 38 ? pen_.fg : pen_.bg) = p[i + 2];
                i += 2;
            } else {
                error_ = "SGR " + std::to_string(v);
                return;
            }
        }
    }

    void put(const std::string& glyph) {
        if (pending_wrap_) {
            x_ = 0;
            line_feed();
        }
        VtCell& c = cell(x_, y_);
        c = pen_;
        c.glyph = glyph;
        last_glyph_ = glyph;
        if (x_ == width_ - 1)
            pending_wrap_ = true;
        else
            ++x_;
    }

    // Erased cells take the current background (xterm's back colour erase), nothing else.
    void blank(int x, int y) {
        VtCell& c = cell(x, y);
        c = VtCell{};
        c.bg = pen_.bg;
    }

    void erase_line(int how) {
        const int from = how == 0 ? x_ : 0;
        const int to = how == 1 ? x_ : width_ - 1;
        for (int x = from; x <= to; ++x)
            blank(x, y_);
    }

    void erase_display(int how) {
        if (how == 2) {
            for (int y = 0; y < height_; ++y)
                for (int x = 0; x < width_; ++x)
                    blank(x, y);
            return;
        }
        erase_line(how);
        if (how == 0)
            for (int y = y_ + 1; y < height_; ++y)
                for (int x = 0; x < width_; ++x)
                    blank(x, y);
        else
            for (int y = 0; y < y_; ++y)
                for (int x = 0; x < width_; ++x)
                    blank(x, y);
    }

    void line_feed() {
        pending_wrap_ = false;
        if (y_ == bottom_)
            scroll_up(top_);
        else
            y_ = clamp_row(y_ + 1);
    }

    void reverse_index() {
        pending_wrap_ = false;
        if (y_ == top_)
            scroll_down(top_);
        else
            y_ = clamp_row(y_ - 1);
    }

    // Rows `from`..bottom_ move up one; the bottom row comes in blank.
    void scroll_up(int from) {
        for (int y = from; y < bottom_; ++y)
            for (int x = 0; x < width_; ++x)
                cell(x, y) = cell(x, y + 1);
        for (int x = 0; x < width_; ++x)
            blank(x, bottom_);
    }

    // Rows `from`..bottom_ move down one; row `from` comes in blank.
    void scroll_down(int from) {
        for (int y = bottom_; y > from; --y)
            for (int x = 0; x < width_; ++x)
                cell(x, y) = cell(x, y - 1);
        for (int x = 0; x < width_; ++x)
            blank(x, from);
    }

    int clamp_row(int y) const { return std::clamp(y, 0, height_ - 1); }
    int clamp_col(int x) const { return std::clamp(x, 0, width_ - 1); }
    VtCell& cell(int x, int y) { return cells_[static_cast<std::size_t>(y * width_ + x)]; }

    int width_, height_;
    int top_ = 0, bottom_;
    int x_ = 0, y_ = 0, saved_x_ = 0, saved_y_ = 0;
    bool pending_wrap_ = false;
    VtCell pen_;
    std::vector<VtCell> cells_;
    State state_ = State::text;
    std::string sequence_;
    std::string utf8_;
    int utf8_need_ = 0;
    std::string last_glyph_ = " ";
    std::string error_;
};

} // namespace termpool::test
