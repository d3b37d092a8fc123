// name_key: ICU's NFKC_Casefold normaliser, from UTF-8 through UTF-16 and back.
#include "hall/name_key.hpp"

#include <unicode/unorm2.h>
#include <unicode/ustring.h>
#include <vector>

namespace termpool::hall {

std::string name_key(std::string_view name) {
    UErrorCode status = U_ZERO_ERROR;
    const UNormalizer2* fold = unorm2_getNFKCCasefoldInstance(&status);
    if (U_FAILURE(status) || name.size() > 4096) // names are 80 bytes; anything else is kept
        return std::string(name);
    // UTF-16 takes at most one unit per UTF-8 byte.
    std::vector<UChar> wide(name.size() + 1);
    int32_t wide_length = 0;
    u_strFromUTF8(wide.data(), static_cast<int32_t>(wide.size()), &wide_length, name.data(),
                  static_cast<int32_t>(name.size()), &status);
    if (U_FAILURE(status))
        return std::string(name);
    // NFKC grows a text by at most 18 times (U+FDFA, one unit, becomes 18); should folding
    // need more, ICU says how much, and the second call has it.
    std::vector<UChar> folded(static_cast<std::size_t>(wide_length) * 18 + 1);
    int32_t folded_length = 0;
    for (int attempt = 0; attempt < 2; ++attempt) {
        status = U_ZERO_ERROR;
        folded_length = unorm2_normalize(fold, wide.data(), wide_length, folded.data(),
                                         static_cast<int32_t>(folded.size()), &status);
        if (status != U_BUFFER_OVERFLOW_ERROR)
            break;
        folded.resize(static_cast<std::size_t>(folded_length) + 1);
    }
    if (U_FAILURE(status))
        return std::string(name);
    std::string out(static_cast<std::size_t>(folded_length) * 3 + 1, '\0');
    int32_t out_length = 0;
    u_strToUTF8(out.data(), static_cast<int32_t>(out.size()), &out_length, folded.data(),
                folded_length, &status);
    if (U_FAILURE(status))
        return std::string(name);
    out.resize(static_cast<std::size_t>(out_length));
    // NFKC makes a space of every wide or no-break space; trimmed at the ends and run together
    // inside, they do not tell two names apart ("Fay" and "Fay" with a no-break space after).
    std::string key;
    for (const char c : out) {
        if (c == ' ' && (key.empty() || key.back() == ' '))
            continue;
        key += c;
    }
    if (!key.empty() && key.back() == ' ')
        key.pop_back();
    return key;
}

bool same_name(std::string_view a, std::string_view b) {
    return !a.empty() && name_key(a) == name_key(b);
}

} // namespace termpool::hall
