#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tendril::dashboard {

// The directory a dashboard serves, and the only files it will read: a request names a path
// relative to the root with '/' separators; it is refused when absolute, when any component is
// "..", when it holds a NUL, or when it resolves — following symbolic links — to a place outside
// the root. Files the server finds by itself (a run's config.yaml, its episodes/) pass the same
// check through contain() and served_file(): a link inside the root never leads a read outside.
class ServedRoot {
 public:
  // Raises Error unless `directory` is an existing directory.
  explicit ServedRoot(const std::filesystem::path& directory);

  // The canonical path `relative` names inside the root (which may not exist), or nothing when
  // the request is refused. "" and "." name the root itself.
  std::optional<std::filesystem::path> resolve(std::string_view relative) const;

  // The canonical path of `path` (absolute, e.g. a resolved directory / "config.yaml"), or
  // nothing when it resolves, following symbolic links, to a place outside the root.
  std::optional<std::filesystem::path> contain(const std::filesystem::path& path) const;

  // contain(path) when that is an existing regular file, else nothing.
  std::optional<std::filesystem::path> served_file(const std::filesystem::path& path) const;

  // Whether `relative` could name a file at all: false when a component is longer than a file
  // name can be, or the whole longer than a path can be (such a path is not found, not refused).
  static bool nameable(std::string_view relative);

  // The '/'-separated path of `inside` (a path under the root) relative to it; "" for the root.
  std::string relative(const std::filesystem::path& inside) const;

  const std::filesystem::path& path() const { return root_; }

 private:
  std::filesystem::path root_;  // canonical
};

}  // namespace tendril::dashboard
