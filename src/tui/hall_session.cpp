// The hall session's loop: the connection (started, lost, tried again), the socket and the
// keyboard read together, the frame drawn, the aim sent at its rate.
#include "tui/hall_session.hpp"

#include <algorithm>
#include <cstdio>

#include "hall/autostart.hpp"
#include "hall/token_store.hpp"

namespace termpool::tui {
namespace {

using namespace std::chrono_literals;

constexpr auto aim_interval = 50ms;  // the rate for the shooter's cue
constexpr int frame_ms = 16;         // while something moves
constexpr int lines_per_round = 500; // messages read before the screen is drawn again

} // namespace

HallSession::HallSession(Terminal& terminal, HallOptions options)
    : term_(terminal), options_(std::move(options)) {
    if (options_.name) {
        name_ = *options_.name;
    } else {
        form_ = Form::name;
    }
}

int HallSession::run() {
    if (form_ != Form::name)
        connect();
    while (running_) {
        if (form_ != Form::name && !stopped_ && client_.closed() && Clock::now() >= retry_at_)
            connect();
        if (!running_)
            break; // the hall was refused
        receive();
        if (app_) {
            app_->step();
            if (const auto copy = driver_->take_sync_request())
                send(hall::Sync{copy->actions, copy->hash});
            if (!app_->running())
                leave_table();
        }
        flush_aim();
        const int w = term_.width(), h = term_.height();
        if (app_) {
            term_.draw(app_->frame(w, h));
        } else {
            LobbyView view;
            compose_lobby(view);
            term_.draw(render_lobby(view, term_.caps(), w, h));
        }
        Input in = term_.read(wait_ms(), client_.fd());
        // What has queued up is taken before the next frame, so that a fast mouse does not
        // lag behind and a burst of messages costs one frame.
        for (int n = 0; in.kind != Input::Kind::none && running_ && n < lines_per_round; ++n) {
            if (in.kind == Input::Kind::watched)
                receive();
            else
                handle(in);
            if (in.kind == Input::Kind::signal)
                break;
            in = term_.read(0, client_.fd());
        }
    }
    // A seat in a game under way waits for us (the server marks it away); nothing to save.
    client_.disconnect();
    return refusal_.empty() ? 0 : 1;
}

int HallSession::wait_ms() const {
    if (app_ && app_->moving())
        return frame_ms;
    if (aim_waiting_)
        return static_cast<int>(aim_interval.count());
    if (form_ != Form::name && !stopped_ && client_.closed()) {
        const auto left = std::chrono::ceil<std::chrono::milliseconds>(retry_at_ - Clock::now());
        return static_cast<int>(std::clamp<long long>(left.count(), 0, 1000));
    }
    return 1000; // the clock in a waiting message, at most
}

void HallSession::connect() {
    // The hall is started when none answers, at the first try and after a server went away
    // (it restores its tables): a second terminal doing the same at once finds it locked.
    const hall::HallReach reach =
        hall::connect_or_start(client_, options_.socket_path, options_.self_exe);
    if (reach.refused) {
        // Not our own hall: nothing more is said to it, nor tried again. run_hall tells why.
        refusal_ = reach.error;
        running_ = false;
        return;
    }
    if (!reach.error.empty()) {
        lost_connection(reach.error);
        return;
    }
    client_.keep_copies(false); // the App plays every action itself
    welcomed_ = false;
    if (token_.empty())
        token_ = hall::load_token(options_.token_dir, name_);
    send(hall::Hello{hall::protocol_version, token_, name_});
}

void HallSession::lost_connection(const std::string& why) {
    client_.disconnect();
    welcomed_ = false;
    if (stopped_)
        return; // the message says why, and r tries again
    if (form_ == Form::name)
        return; // the name was refused: the prompt asks again, and nothing is tried meanwhile
    if (app_ && table_ != 0) {
        rejoin_table_ = table_;
        rejoin_seat_ = seat_;
    }
    const auto wait = backoff_.next();
    retry_at_ = Clock::now() + wait;
    char delay[32];
    std::snprintf(delay, sizeof delay, "%.2g", std::chrono::duration<double>(wait).count());
    message_ = "The hall is away (" + why + "); trying again in " + delay + " s (r: now)";
    if (app_)
        driver_->set_notice(std::string("The hall is away: trying again in ") + delay +
                            " s; your seat waits");
}

void HallSession::receive() {
    if (client_.closed())
        return;
    for (int n = 0; n < lines_per_round; ++n) {
        if (auto message = client_.receive(0ms))
            dispatch(*message);
        else if (!client_.line_waiting())
            break;
    }
    if (client_.closed() && !client_.line_waiting())
        lost_connection(client_.broken().empty() ? "the connection closed" : client_.broken());
}

void HallSession::send(const hall::ClientMessage& message) {
    if (!client_.closed())
        client_.send(message);
}

void HallSession::flush_aim() {
    const auto now = Clock::now();
    if (!aim_waiting_ || !welcomed_ || now - aim_sent_at_ < aim_interval)
        return;
    send(hall::Aim{*aim_waiting_});
    aim_waiting_.reset();
    aim_sent_at_ = now;
}

void HallSession::handle(const Input& in) {
    if (in.kind == Input::Kind::signal) {
        running_ = false;
        return;
    }
    if (form_ == Form::name) {
        handle_name_key(in);
        return;
    }
    if (app_) {
        app_->handle(in);
        return;
    }
    if (form_ == Form::create) {
        handle_create_key(in);
        return;
    }
    handle_lobby_key(in);
}

} // namespace termpool::tui
