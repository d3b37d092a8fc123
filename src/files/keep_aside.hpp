#pragma once
// A file that cannot be read is never overwritten or deleted: it is moved aside under a name
// of its own, so that the player can look at it (or mend it) later.

#include <optional>
#include <string>

namespace termpool {

/// Renames `path` to `path`.bad, or `path`.bad.1, .bad.2, ... when those exist: never over an
/// existing file. Returns the new name, or nothing (with `error`) when it could not be moved.
std::optional<std::string> keep_aside(const std::string& path, std::string& error);

} // namespace termpool
