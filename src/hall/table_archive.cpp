// The hall's archive folder: a table's file moved aside by link and unlink, so that an older
// file of the same name is never replaced.

#include "hall/table_archive.hpp"

#include <cerrno>
#include <cstring>
#include <sys/stat.h>
#include <unistd.h>

#include "hall/hall_state.hpp"

namespace termpool::hall {

std::string archive_table(const std::string& dir, int number) {
    const std::string from = table_path(dir, number);
    struct stat info {};
    if (::lstat(from.c_str(), &info) != 0)
        return errno == ENOENT ? "" : from + ": " + std::strerror(errno);
    const std::string folder = dir + "/archive";
    if (::mkdir(folder.c_str(), 0700) != 0 && errno != EEXIST)
        return folder + ": " + std::strerror(errno);
    const std::string name = folder + "/table-" + std::to_string(number) + ".save";
    // A bound on the names tried: a folder of a thousand of one table's files is full enough.
    for (int k = 0; k < 1000; ++k) {
        const std::string to = k == 0 ? name : name + "." + std::to_string(k);
        if (::link(from.c_str(), to.c_str()) == 0) {
            ::unlink(from.c_str());
            return {};
        }
        if (errno != EEXIST)
            return to + ": " + std::strerror(errno);
    }
    return name + ": a thousand archived files of this table already";
}

} // namespace termpool::hall
