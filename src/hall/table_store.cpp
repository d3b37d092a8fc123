#include "hall/table_store.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fstream>
#include <sstream>
#include <termpool/match.hpp>
#include <termpool/text_numbers.hpp>
#include <unistd.h>

#include "hall/unique_fd.hpp"

namespace termpool::hall {

namespace {

std::string file_of(const std::string& dir, int number) {
    return dir + "/table-" + std::to_string(number) + ".save";
}

} // namespace

std::string store_table(const std::string& dir, const StoredTable& table) {
    std::string text;
    for (int s = 0; s < 2; ++s)
        text += "# seat" + std::to_string(s + 1) + "-token " +
                (table.seat_tokens[s].empty() ? std::string("-") : table.seat_tokens[s]) + "\n";
    text += format_record(table.record);

    // A crash leaves the old file or the new one, never half of one.
    const std::string path = file_of(dir, table.number);
    const std::string temporary = path + ".tmp";
    {
        const UniqueFd fd(
            ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600));
        if (!fd)
            return temporary + ": " + std::strerror(errno);
        for (std::size_t done = 0; done < text.size();) {
            const ssize_t n = ::write(fd.get(), text.data() + done, text.size() - done);
            if (n < 0 && errno == EINTR)
                continue;
            if (n <= 0)
                return temporary + ": " + std::strerror(errno);
            done += static_cast<std::size_t>(n);
        }
        if (::fsync(fd.get()) != 0)
            return temporary + ": " + std::strerror(errno);
    }
    if (::rename(temporary.c_str(), path.c_str()) != 0)
        return path + ": " + std::strerror(errno);
    return {};
}

void drop_stored_table(const std::string& dir, int number) {
    ::unlink(file_of(dir, number).c_str());
}

std::vector<StoredTable> load_stored_tables(const std::string& dir,
                                            std::vector<std::string>& problems) {
    std::vector<int> numbers;
    if (DIR* d = ::opendir(dir.c_str())) {
        while (const dirent* entry = ::readdir(d)) {
            const std::string name = entry->d_name;
            if (!name.starts_with("table-") || !name.ends_with(".save"))
                continue;
            const auto n = parse_integer(std::string_view(name).substr(6, name.size() - 11));
            if (n && *n >= 1 && *n <= 9999)
                numbers.push_back(static_cast<int>(*n));
        }
        ::closedir(d);
    }
    std::sort(numbers.begin(), numbers.end());

    std::vector<StoredTable> tables;
    for (const int number : numbers) {
        const std::string path = file_of(dir, number);
        std::ifstream in(path, std::ios::binary);
        std::stringstream buffer;
        buffer << in.rdbuf();
        const std::string text = buffer.str();
        StoredTable table;
        table.number = number;
        // The token lines come first; the record reader sees only the record.
        std::size_t start = 0;
        for (int s = 0; s < 2; ++s) {
            const std::string key = "# seat" + std::to_string(s + 1) + "-token ";
            const std::size_t end = text.find('\n', start);
            if (end == std::string::npos || text.compare(start, key.size(), key) != 0)
                break;
            const std::string value = text.substr(start + key.size(), end - start - key.size());
            if (value != "-")
                table.seat_tokens[s] = value;
            start = end + 1;
        }
        const int skipped = start == 0 ? 0 : 2;
        auto parsed = parse_record(std::string_view(text).substr(start));
        if (const auto* e = std::get_if<RecordError>(&parsed)) {
            problems.push_back(path + ":" + std::to_string(e->line + skipped) + ": " + e->message);
            continue;
        }
        table.record = std::get<GameRecord>(parsed);
        if (const auto replayed = Match::replay(table.record);
            const auto* e = std::get_if<RecordError>(&replayed)) {
            problems.push_back(path + ":" + std::to_string(e->line) + ": " + e->message);
            continue;
        }
        tables.push_back(std::move(table));
    }
    return tables;
}

} // namespace termpool::hall
