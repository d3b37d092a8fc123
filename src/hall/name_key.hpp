#pragma once
// The form in which the hall compares names: one person, one name, however it is typed.

#include <string>
#include <string_view>

namespace termpool::hall {

/// `name` as the hall compares it with the names already in it: Unicode NFKC with case
/// folding (ICU's NFKC_Casefold), so that "Ann", "ANN", "ａｎｎ" (full width) and an "Å" typed
/// as A and a combining ring or as one character each give one key, and the invisible
/// characters that NFKC_Casefold drops do not tell two names apart; nor do spaces of any kind
/// (NFKC makes each a space), trimmed at the ends and run together inside. Text that is not
/// valid UTF-8 (a name the protocol would refuse) is its own key.
std::string name_key(std::string_view name);

/// Whether two names are one person's: equal however typed (their name_key); an empty name is
/// nobody's.
bool same_name(std::string_view a, std::string_view b);

} // namespace termpool::hall
