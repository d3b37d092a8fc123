// What happened at the table, told and kept: the verdict line holds the last shot's verdict
// and what followed until the player here acts again, and `l` opens the rack's log, paged
// like the help. The overlays' keys (the log, the help, the questions) are read here too.

#include <algorithm>
#include <string>
#include <termpool/game_registry.hpp>

#include "tui/app.hpp"
#include "tui/help_text.hpp"
#include "tui/rack_log.hpp"

namespace termpool::tui {
namespace {

constexpr std::size_t verdicts_kept = 3; // the player's own verdict and the latest two after it

} // namespace

void App::tell(std::string news) {
    // A replay shows the shot just played; at the table the player's own verdict stays first.
    if (driver_->watching())
        verdicts_.clear();
    verdicts_.push_back(std::move(news));
    if (verdicts_.size() > verdicts_kept)
        verdicts_.erase(verdicts_.begin() + 1);
}

void App::player_acts() {
    verdicts_.clear();
}

std::string App::said() const {
    std::string text = driver_->notice();
    for (const std::string& verdict : verdicts_)
        text += (text.empty() ? "" : ". ") + verdict;
    if (!message_.empty())
        text += (text.empty() ? "" : ". ") + message_;
    return text;
}

void App::open_log() {
    // The shots told so far: one rolling now is in the log once its verdict is told.
    log_ =
        driver_->referee() ? rack_log_.lines(driver_->match().rack()) : std::vector<std::string>{};
    log_page_ = 0;
}

std::string App::log_page_text() const {
    const std::vector<std::string>& lines = *log_;
    const std::vector<std::size_t> starts = log_page_starts(lines, term_.width(), term_.height());
    const int pages = static_cast<int>(starts.size());
    const int page = std::min(log_page_, pages - 1);
    std::string text = !driver_->referee()
                           ? "Practice: no referee, no log"
                           : std::string(game_row(game().type()).words.heading) + " " +
                                 std::to_string(driver_->match().rack()) + ": the shots";
    if (lines.empty() && driver_->referee())
        text += "\n\nNo shot yet";
    const std::size_t end =
        page + 1 < pages ? starts[static_cast<std::size_t>(page) + 1] : lines.size();
    for (std::size_t i = starts[static_cast<std::size_t>(page)]; i < end; ++i)
        text += "\n" + lines[i];
    text += "\n\n";
    if (pages > 1)
        text += "page " + std::to_string(page + 1) + "/" + std::to_string(pages) +
                (page + 1 < pages ? ": Space more, " : ": k back, ");
    return text + "Esc closes";
}

bool App::handle_log(const Input& in) {
    if (!log_)
        return false;
    const int last =
        static_cast<int>(log_page_starts(*log_, term_.width(), term_.height()).size()) - 1;
    const int key = in.kind == Input::Kind::key ? in.key : 0;
    const std::string& t = in.text;
    if (t == " " || t == "j" || key == key_page_down || key == key_down)
        log_page_ = std::min(log_page_ + 1, last);
    else if (t == "k" || key == key_page_up || key == key_up)
        log_page_ = std::max(std::min(log_page_, last) - 1, 0);
    else if (t == "q" || t == "l" || key == key_escape || key == key_enter ||
             (in.kind == Input::Kind::mouse && in.clicked))
        log_.reset();
    return true;
}

bool App::handle_overlay(const Input& in) {
    if (handle_log(in))
        return true;
    if (confirm_concede_) {
        if (in.kind == Input::Kind::mouse && !in.clicked)
            return true;
        confirm_concede_ = false;
        if (in.kind == Input::Kind::text && (in.text == "y" || in.text == "Y")) {
            player_acts();
            concede();
        }
        return true;
    }
    if (confirm_quit_) {
        // y, or q again (q q quits, as in many terminal programs).
        if (in.kind == Input::Kind::text && (in.text == "y" || in.text == "Y" || in.text == "q"))
            running_ = false;
        else if (in.kind != Input::Kind::mouse || in.clicked)
            confirm_quit_ = false;
        return true;
    }
    if (!help_)
        return false;
    // Pages forward and back; Esc, q, ?, Enter or a click close it.
    const int last = help_page_count(term_.width(), term_.height()) - 1;
    const int key = in.kind == Input::Kind::key ? in.key : 0;
    const std::string& t = in.text;
    if (t == " " || t == "j" || key == key_page_down || key == key_down)
        help_page_ = std::min(help_page_ + 1, last);
    else if (t == "k" || key == key_page_up || key == key_up)
        help_page_ = std::max(std::min(help_page_, last) - 1, 0);
    else if (t == "q" || t == "?" || key == key_escape || key == key_enter ||
             (in.kind == Input::Kind::mouse && in.clicked)) {
        help_ = false;
        help_page_ = 0;
    }
    return true;
}

} // namespace termpool::tui
