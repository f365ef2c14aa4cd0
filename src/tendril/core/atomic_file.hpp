#pragma once

#include <filesystem>
#include <string_view>

namespace tendril {

// Writes `bytes` to a temporary file beside `file`, flushes it to disk and renames it over
// `file`: a crash at any point leaves either the old file or the new one, never a mixture.
// Raises Error naming `file` (and leaves it untouched) if any step fails. `what` names the
// kind of file in messages ("checkpoint", "replay buffer").
void write_file_atomically(const std::filesystem::path& file, std::string_view bytes,
                           std::string_view what);

// Like write_file_atomically, but never replaces anything: raises Error naming `file` if it
// already exists (also when it appears while writing — the final step is an exclusive link).
void write_new_file_atomically(const std::filesystem::path& file, std::string_view bytes,
                               std::string_view what);

}  // namespace tendril
