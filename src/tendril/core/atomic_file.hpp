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

// Appends `bytes` to `file` (created if missing). Raises Error naming `file` and the system's
// reason if any byte cannot be written (a full disk, an I/O error, a file size limit); a
// partial append is then cut off again, so the file never ends in half a row.
void append_to_file(const std::filesystem::path& file, std::string_view bytes,
                    std::string_view what);

// Whether `name` is the name of a temporary file `write_file_atomically` leaves behind when
// its process is killed ("<file>.tmp.<pid>"): removable once no process writes beside it.
bool is_atomic_write_leftover(const std::string& name);

}  // namespace tendril
