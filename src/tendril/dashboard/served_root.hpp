#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tendril::dashboard {

// The directory a dashboard serves, and the only files it will read: a request names a path
// relative to the root with '/' separators; it is refused when absolute, when any component is
// "..", when it holds a NUL, or when it resolves — following symbolic links — to a place outside
// the root.
class ServedRoot {
 public:
  // Raises Error unless `directory` is an existing directory.
  explicit ServedRoot(const std::filesystem::path& directory);

  // The canonical path `relative` names inside the root (which may not exist), or nothing when
  // the request is refused. "" and "." name the root itself.
  std::optional<std::filesystem::path> resolve(std::string_view relative) const;

  // The '/'-separated path of `inside` (a path under the root) relative to it; "" for the root.
  std::string relative(const std::filesystem::path& inside) const;

  const std::filesystem::path& path() const { return root_; }

 private:
  std::filesystem::path root_;  // canonical
};

}  // namespace tendril::dashboard
