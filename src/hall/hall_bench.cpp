// `termpool hall bench`: tables of computer players through a real server over its Unix socket,
// with the figures a host cares about: actions a second, how long an action takes to reach
// everyone at its table, the server's CPU and memory, and at the end a check that nothing was
// lost.

#include "hall/hall_bench.hpp"

#include "support/text_numbers.hpp"
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <latch>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <termpool/computer.hpp>
#include <termpool/game_registry.hpp>
#include <thread>
#include <unistd.h>
#include <vector>

#include "files/file_limits.hpp"
#include "files/read_file.hpp"
#include "hall/client.hpp"

namespace termpool::hall {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

constexpr const char* usage =
    "usage: termpool hall bench [--tables N] [--seconds S] [--think MS] [--seed S]\n"
    "  plays N tables (default 10, at most 500) of two easy computers through a hall server\n"
    "  on a private socket for S seconds (default 10, at most 600), each taking MS ms\n"
    "  (default 100, at least 50: the hall takes 20 actions a second from a seat) between\n"
    "  actions as a player would, then checks every table\n";

constexpr milliseconds wait_limit{5000}; // the longest any one answer may take

struct Options {
    int tables = 10;
    int seconds = 10;
    int think_ms = 100; // a player's pause between actions (people take seconds)
    std::uint64_t seed = 1;
};

// What one table's driver measured.
struct TableRun {
    std::vector<double> round_trips_ms; // an action sent until both players had it
    std::uint64_t hash[2] = {0, 0};     // each player's copy at the end
    std::size_t actions = 0;            // the last action number both players saw
    int table = 0;                      // its number at the server
    std::string problem;                // empty when all went well
};

// The server as a child process, so that its CPU time and peak memory are its own.
class ServerProcess {
public:
    std::string start(const std::string& socket, const std::string& state, const std::string& log,
                      int max_tables) {
        const std::string self = "/proc/self/exe";
        pid_ = ::fork();
        if (pid_ < 0)
            return std::string("fork: ") + std::strerror(errno);
        if (pid_ == 0) {
            // The server's log goes to a file: the figures are what the bench prints.
            const int fd =
                ::open(log.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
            if (fd >= 0)
                ::dup2(fd, STDERR_FILENO);
            const std::string tables = std::to_string(max_tables);
            const std::string clients = std::to_string(2 * max_tables + 16);
            ::execl(self.c_str(), "termpool", "hall", "serve", "--socket", socket.c_str(),
                    "--state", state.c_str(), "--max-tables", tables.c_str(), "--max-clients",
                    clients.c_str(), static_cast<char*>(nullptr));
            ::_exit(127);
        }
        return {};
    }
    // CPU seconds (user + system) and peak resident memory (kB) so far.
    std::pair<double, long> usage() const {
        double cpu = 0;
        std::string unread;
        const std::string text =
            read_whole_file("/proc/" + std::to_string(pid_) + "/stat", unread, max_proc_file_bytes)
                .value_or("");
        // Fields after the command's closing parenthesis; utime and stime are the 12th and 13th.
        if (const std::size_t close = text.rfind(')'); close != std::string::npos) {
            std::istringstream rest(text.substr(close + 2));
            std::string field;
            unsigned long long utime = 0, stime = 0;
            for (int i = 1; i <= 13 && rest >> field; ++i) {
                if (i == 12)
                    utime = std::strtoull(field.c_str(), nullptr, 10);
                if (i == 13)
                    stime = std::strtoull(field.c_str(), nullptr, 10);
            }
            cpu = static_cast<double>(utime + stime) / static_cast<double>(::sysconf(_SC_CLK_TCK));
        }
        long peak_kb = 0;
        std::istringstream status(read_whole_file("/proc/" + std::to_string(pid_) + "/status",
                                                  unread, max_proc_file_bytes)
                                      .value_or(""));
        for (std::string line; std::getline(status, line);)
            if (line.starts_with("VmHWM:"))
                peak_kb = std::strtol(line.c_str() + 6, nullptr, 10);
        return {cpu, peak_kb};
    }
    // SIGTERM (the server saves and exits), then at most 5 s; SIGKILL if it is still there.
    int stop() {
        if (pid_ <= 0)
            return -1;
        ::kill(pid_, SIGTERM);
        int status = 0;
        const auto until = Clock::now() + wait_limit;
        while (::waitpid(pid_, &status, WNOHANG) == 0) {
            if (Clock::now() > until) {
                ::kill(pid_, SIGKILL);
                ::waitpid(pid_, &status, 0);
                break;
            }
            std::this_thread::sleep_for(milliseconds(10));
        }
        pid_ = -1;
        return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    ~ServerProcess() { stop(); }

private:
    pid_t pid_ = -1;
};

std::optional<Options> parse(const std::vector<std::string>& args, std::string& error) {
    Options o;
    for (std::size_t i = 1; i < args.size(); i += 2) {
        if (i + 1 >= args.size()) {
            error = args[i] + " needs a value";
            return std::nullopt;
        }
        const auto n = parse_uint64(args[i + 1]);
        if (args[i] == "--tables" && n && *n >= 1 && *n <= 500)
            o.tables = static_cast<int>(*n);
        else if (args[i] == "--seconds" && n && *n >= 1 && *n <= 600)
            o.seconds = static_cast<int>(*n);
        else if (args[i] == "--think" && n && *n >= 50 && *n <= 10000) // a seat may act 20 a second
            o.think_ms = static_cast<int>(*n);
        else if (args[i] == "--seed" && n)
            o.seed = *n;
        else {
            error = "bad option '" + args[i] + " " + args[i + 1] + "'";
            return std::nullopt;
        }
    }
    return o;
}

// Both players' copies have applied action `seq`: "" then, else what went wrong (the server's
// error to the one who acted, or no answer).
std::string both_have(HallClient (&players)[2], HallClient& actor, int table, std::size_t seq) {
    for (HallClient& p : players) {
        std::string refused;
        const auto got = p.wait_for(
            [&](const ServerMessage& m) {
                if (const auto* e = std::get_if<Error>(&m); e && &p == &actor) {
                    refused = std::string(error_code_name(e->code)) + ": " + e->text;
                    return true;
                }
                const auto* done = std::get_if<ActionDone>(&m);
                return done && done->table == table && done->seq >= seq;
            },
            wait_limit);
        if (!refused.empty())
            return "refused: " + refused;
        if (!got)
            return "no answer within 5 s";
    }
    return {};
}

// The tables play together: every table's players are seated before any table plays, and
// stay connected until every table stopped. The hellos, sits and leaves of a hundred tables
// coming at once (each a lobby change for everyone, each sit or leave a save) are not what an
// action's round trip measures.
class Together {
public:
    Together(std::latch& seated, std::latch& stopped) : seated_(seated), stopped_(stopped) {}
    Together(const Together&) = delete;
    Together& operator=(const Together&) = delete;
    // Seated: waits for the other tables.
    void start() {
        arrived_ = true;
        seated_.arrive_and_wait();
    }
    // Stopped (or failed): waits for the other tables before the players go.
    ~Together() {
        if (!arrived_)
            seated_.count_down();
        stopped_.arrive_and_wait();
    }

private:
    std::latch& seated_;
    std::latch& stopped_;
    bool arrived_ = false;
};

// One table: two clients sit, each plays its seat with its own easy computer, as a person at a
// terminal would (the hall hears only actions), until `stop`. Its first action waits `offset`
// more than the others': tables that all started at once and paused alike would act in step,
// which people at a hundred tables do not.
TableRun drive_table(const std::string& socket, int index, std::uint64_t seed, int think_ms,
                     milliseconds offset, const std::atomic<bool>& stop, std::latch& seated,
                     std::latch& stopped) {
    TableRun run;
    HallClient players[2];
    Together together(seated, stopped); // destroyed before the players go
    for (int p = 0; p < 2; ++p) {
        // A hall takes so many newcomers at once: a client told "full" tries again, waiting a
        // little longer each time, as a player's terminal would.
        const std::string name = "Bench " + std::to_string(index) + (p == 0 ? "a" : "b");
        std::string problem = "no answer";
        milliseconds pause{10};
        for (const auto until = Clock::now() + wait_limit; Clock::now() < until;
             pause = std::min(pause * 2, milliseconds(500))) {
            problem = players[p].connect(socket);
            if (problem.empty())
                problem = players[p].hello(name, "", wait_limit);
            if (problem.empty())
                break;
            players[p].disconnect();
            std::this_thread::sleep_for(pause);
        }
        if (!problem.empty()) {
            run.problem = "hello: " + problem;
            return run;
        }
    }
    // A race long enough to outlast the bench: the table never runs out of racks.
    players[0].send(Create{*parse_game_type("9ball"), TableSize::nine_foot, max_race_to});
    const auto created = players[0].wait_for(
        [](const ServerMessage& m) { return std::holds_alternative<Created>(m); }, wait_limit);
    if (!created) {
        run.problem = "no table created";
        return run;
    }
    const int table = std::get<Created>(*created).table;
    run.table = table;
    for (int p = 0; p < 2; ++p) {
        players[p].send(Sit{table, p + 1});
        if (!players[p].wait_for(
                [&](const ServerMessage&) { return players[p].match(table) != nullptr; },
                wait_limit)) {
            run.problem = "no record after sitting";
            return run;
        }
    }
    ComputerPlayer computers[2] = {ComputerPlayer(Level::easy, seed * 2 + 1),
                                   ComputerPlayer(Level::easy, seed * 2 + 2)};
    together.start();
    std::this_thread::sleep_for(offset);
    while (!stop) {
        const Match* view = players[0].match(table);
        if (!view || view->pending().kind == Pending::over)
            break;
        const PendingAction pending = view->pending();
        const int seat = pending.player;
        HallClient& actor = players[seat - 1];
        ComputerPlayer& computer = computers[seat - 1];
        const Game& game = actor.match(table)->game();
        const std::size_t seq = view->record().actions.size() + 1;
        ClientMessage message = NextRack{};
        if (pending.kind == Pending::place) {
            RecordedAction a;
            a.kind = RecordedAction::Kind::place;
            a.place = computer.place_cue_ball(game);
            message = Act{a};
        } else if (pending.kind == Pending::choose) {
            RecordedAction a;
            a.kind = RecordedAction::Kind::choose;
            a.choice = computer.choose(game);
            message = Act{a};
        } else if (pending.kind == Pending::shoot) {
            const ComputerShot shot = computer.shot(game);
            RecordedAction a;
            a.strike = shot.strike;
            a.call = shot.call;
            message = Act{a};
        }
        std::this_thread::sleep_for(milliseconds(think_ms));
        const auto sent = Clock::now();
        const std::string problem =
            actor.send(message) ? both_have(players, actor, table, seq) : "the server went away";
        if (!problem.empty()) {
            run.problem = "action " + std::to_string(seq) + ": " + problem;
            return run;
        }
        run.round_trips_ms.push_back(
            std::chrono::duration<double, std::milli>(Clock::now() - sent).count());
    }
    for (int p = 0; p < 2; ++p) {
        const Match* m = players[p].match(table);
        run.hash[p] = m ? m->state_hash() : 0;
        if (p == 0 && m)
            run.actions = m->record().actions.size();
        if (players[p].mismatches() != 0)
            run.problem = "a player's copy disagreed with the server";
    }
    return run;
}

// What the server holds for `table`, as a late spectator gets it: the hash of the replayed
// record, and the action count.
std::optional<std::pair<std::uint64_t, std::size_t>> server_state(const std::string& socket,
                                                                  int table) {
    HallClient watcher;
    if (!watcher.connect(socket).empty() ||
        !watcher.hello("Check " + std::to_string(table), "", wait_limit).empty())
        return std::nullopt;
    watcher.send(Watch{table});
    const auto end = watcher.wait_for(
        [&](const ServerMessage& m) {
            const auto* e = std::get_if<RecordEnd>(&m);
            return e && e->table == table;
        },
        wait_limit);
    const Match* m = watcher.match(table);
    if (!end || !m || m->state_hash() != std::get<RecordEnd>(*end).hash)
        return std::nullopt;
    return std::pair{m->state_hash(), m->record().actions.size()};
}

double percentile(std::vector<double> v, double q) {
    if (v.empty())
        return 0;
    std::sort(v.begin(), v.end());
    const auto at = static_cast<std::size_t>(q * static_cast<double>(v.size() - 1));
    return v[at];
}

} // namespace

int hall_bench_command(const std::vector<std::string>& args) {
    if (std::ranges::any_of(args,
                            [](const std::string& a) { return a == "-h" || a == "--help"; })) {
        std::fputs(usage, stdout);
        return 0;
    }
    std::string error;
    const auto options = parse(args, error);
    if (!options) {
        std::fprintf(stderr, "termpool hall bench: %s\n%s", error.c_str(), usage);
        return 2;
    }
    // The server's socket and tables go in a private folder under $TMPDIR (or /tmp): its
    // saves are synced as a real hall's are, so the disk under it counts in the figures.
    const char* tmp = std::getenv("TMPDIR");
    std::string folder_template =
        std::string(tmp && *tmp ? tmp : "/tmp") + "/termpool-hall-bench-XXXXXX";
    const char* folder = ::mkdtemp(folder_template.data());
    if (!folder) {
        std::fprintf(stderr, "termpool hall bench: mkdtemp: %s\n", std::strerror(errno));
        return 1;
    }
    const std::string socket = std::string(folder) + "/hall.sock";
    const std::string state = std::string(folder) + "/state";
    ServerProcess server;
    const std::string log = std::string(folder) + "/server.log";
    if (std::string e = server.start(socket, state, log, options->tables); !e.empty()) {
        std::fprintf(stderr, "termpool hall bench: %s\n", e.c_str());
        return 1;
    }
    // The server is up once it answers.
    bool up = false;
    for (const auto until = Clock::now() + wait_limit; !up && Clock::now() < until;) {
        HallClient probe;
        up = probe.connect(socket).empty();
        if (!up)
            std::this_thread::sleep_for(milliseconds(20));
    }
    if (!up) {
        std::fprintf(stderr, "termpool hall bench: the server did not start\n");
        return 1;
    }

    std::atomic<bool> stop{false};
    std::latch seated(options->tables);
    std::latch stopped(options->tables);
    std::vector<TableRun> runs(static_cast<std::size_t>(options->tables));
    std::vector<std::thread> drivers;
    for (int t = 0; t < options->tables; ++t)
        drivers.emplace_back([&, t] {
            // The tables' first actions spread evenly over one pause.
            const milliseconds offset{options->think_ms * t / options->tables};
            runs[static_cast<std::size_t>(t)] =
                drive_table(socket, t + 1, options->seed * 1000 + static_cast<std::uint64_t>(t),
                            options->think_ms, offset, stop, seated, stopped);
        });
    seated.wait(); // each driver waits at most a few wait_limits for its hellos and sits
    const auto start = Clock::now();
    std::this_thread::sleep_for(std::chrono::seconds(options->seconds));
    stop = true;
    for (std::thread& d : drivers)
        d.join();
    const double wall = std::chrono::duration<double>(Clock::now() - start).count();
    const auto [cpu, peak_kb] = server.usage();

    // Every table as the server holds it against both players' copies.
    std::vector<double> trips;
    std::size_t actions = 0;
    int bad = 0;
    for (int t = 0; t < options->tables; ++t) {
        const TableRun& run = runs[static_cast<std::size_t>(t)];
        trips.insert(trips.end(), run.round_trips_ms.begin(), run.round_trips_ms.end());
        actions += run.round_trips_ms.size();
        const auto held = run.table ? server_state(socket, run.table) : std::nullopt;
        const bool agree = run.problem.empty() && held && held->first == run.hash[0] &&
                           held->first == run.hash[1] && held->second == run.actions;
        if (!agree) {
            ++bad;
            std::fprintf(stderr, "table %d: %s\n", t + 1,
                         run.problem.empty() ? "the server's record and the players disagree"
                                             : run.problem.c_str());
        }
    }
    const int exit_status = server.stop();
    std::printf("hall bench: %d tables of two easy computers, %d s, %d ms between actions, "
                "seed %llu\n",
                options->tables, options->seconds, options->think_ms,
                static_cast<unsigned long long>(options->seed));
    std::printf("actions            %zu (%.0f/s)\n", actions, static_cast<double>(actions) / wall);
    std::printf("round trip         p50 %.2f ms, p99 %.2f ms, max %.2f ms (sent until both "
                "players had it)\n",
                percentile(trips, 0.5), percentile(trips, 0.99), percentile(trips, 1.0));
    // The server's own time for each action, which the round trip includes; its log has it,
    // each line after its time.
    std::string log_problem;
    std::istringstream server_log(
        read_whole_file(log, log_problem, max_bench_log_bytes).value_or(""));
    if (!log_problem.empty())
        std::printf("server figures     not read: %s\n", log_problem.c_str());
    for (std::string line; std::getline(server_log, line);)
        for (const std::string figure : {"handling", "saving"})
            if (const std::string prefix = "termpool hall: " + figure + ": ";
                line.find(prefix) != std::string::npos)
                std::printf("server %-12s%s\n", figure.c_str(),
                            line.c_str() + line.find(prefix) + prefix.size());
    std::printf("server CPU         %.2f s (%.1f%% of one core)\n", cpu, 100 * cpu / wall);
    std::printf("server peak RSS    %.1f MB\n", static_cast<double>(peak_kb) / 1024);
    std::printf("tables checked     %d of %d agree with the server's record%s\n",
                options->tables - bad, options->tables,
                exit_status == 0 ? "" : " (the server did not exit cleanly)");
    if (bad == 0 && exit_status == 0)
        std::filesystem::remove_all(folder);
    else
        std::printf("the server's log and tables are kept in %s\n", folder);
    return bad == 0 && exit_status == 0 ? 0 : 1;
}

} // namespace termpool::hall
