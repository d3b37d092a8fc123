#include <algorithm>
#include <termpool/text_lines.hpp>

namespace termpool {
namespace {

constexpr std::string_view blanks = " \t\r\v\f";

} // namespace

std::vector<TextLine> text_lines(std::string_view text) {
    std::vector<TextLine> lines;
    int number = 0;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        lines.push_back({++number, line});
        start = end + 1;
    }
    return lines;
}

std::string_view strip_comment(std::string_view line) {
    return line.substr(0, line.find('#'));
}

std::vector<std::string_view> split_fields(std::string_view line) {
    std::vector<std::string_view> fields;
    for (;;) {
        const std::size_t first = line.find_first_not_of(blanks);
        if (first == std::string_view::npos)
            return fields;
        line.remove_prefix(first);
        const std::size_t last = std::min(line.find_first_of(blanks), line.size());
        fields.push_back(line.substr(0, last));
        line.remove_prefix(last);
    }
}

} // namespace termpool
