#include "player/save_read.hpp"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace termpool {
namespace {

std::string problem(const std::string& path, const char* what) {
    return path + ": " + what;
}

// The file at `path`, at most max_save_bytes of a regular file; nothing when it is missing
// (no error) or cannot be read (error). Opened without blocking, so that a FIFO put in a
// save's place cannot hang the listing.
std::optional<std::string> read_bounded(const std::string& path, std::string& error) {
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
    if (fd < 0) {
        if (errno != ENOENT)
            error = problem(path, "cannot open") + ": " + std::strerror(errno);
        return std::nullopt;
    }
    struct stat st {};
    std::optional<std::string> text;
    if (::fstat(fd, &st) != 0)
        error = problem(path, "cannot read") + ": " + std::strerror(errno);
    else if (!S_ISREG(st.st_mode))
        error = problem(path, "not a regular file");
    else if (static_cast<std::size_t>(st.st_size) > max_save_bytes)
        error = problem(path, "too large for a save");
    else
        text.emplace();
    char buffer[8192];
    while (text) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR)
            continue;
        if (n < 0) {
            error = problem(path, "cannot read") + ": " + std::strerror(errno);
            text.reset();
        } else if (n == 0) {
            break;
        } else if (text->size() + static_cast<std::size_t>(n) > max_save_bytes) {
            error = problem(path, "too large for a save"); // it grew while being read
            text.reset();
        } else {
            text->append(buffer, static_cast<std::size_t>(n));
        }
    }
    ::close(fd);
    return text;
}

} // namespace

std::variant<Match, RecordError> load_game(const std::string& text) {
    auto parsed = parse_record(text);
    if (auto* bad = std::get_if<RecordError>(&parsed))
        return *bad;
    return Match::replay(std::get<GameRecord>(parsed));
}

bool finished(const Match& game) {
    return game.pending().kind == Pending::over;
}

SaveContents read_save(const std::string& path) {
    SaveContents save;
    save.text = read_bounded(path, save.error);
    if (!save.text)
        return save;
    auto loaded = load_game(*save.text);
    if (auto* bad = std::get_if<RecordError>(&loaded))
        save.problem = *bad;
    else
        save.game.emplace(std::move(std::get<Match>(loaded)));
    return save;
}

} // namespace termpool
