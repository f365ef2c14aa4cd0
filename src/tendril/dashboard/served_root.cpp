#include "tendril/dashboard/served_root.hpp"

#include <climits>
#include <system_error>

#include "tendril/core/error.hpp"

namespace tendril::dashboard {

namespace fs = std::filesystem;

ServedRoot::ServedRoot(const fs::path& directory) {
  std::error_code error;
  root_ = fs::canonical(directory, error);
  require(!error && fs::is_directory(root_), "not a directory", directory.string());
}

std::optional<fs::path> ServedRoot::resolve(std::string_view relative) const {
  if (relative.find('\0') != std::string_view::npos) return std::nullopt;
  if (!relative.empty() && relative.front() == '/') return std::nullopt;
  fs::path joined = root_;
  std::size_t start = 0;
  while (start <= relative.size()) {
    const std::size_t end = std::min(relative.find('/', start), relative.size());
    const std::string_view part = relative.substr(start, end - start);
    if (part == "..") return std::nullopt;
    if (!part.empty() && part != ".") joined /= fs::path(std::string(part));
    start = end + 1;
  }
  return contain(joined);
}

std::optional<fs::path> ServedRoot::contain(const fs::path& path) const {
  // Follows every symbolic link that exists along the path.
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(path, error);
  if (error) return std::nullopt;
  const auto [root_end, inside_end] =
      std::mismatch(root_.begin(), root_.end(), resolved.begin(), resolved.end());
  if (root_end != root_.end()) return std::nullopt;
  return resolved;
}

std::optional<fs::path> ServedRoot::served_file(const fs::path& path) const {
  std::optional<fs::path> inside = contain(path);
  std::error_code error;
  if (!inside || !fs::is_regular_file(*inside, error)) return std::nullopt;
  return inside;
}

bool ServedRoot::nameable(std::string_view relative) {
  if (relative.size() >= PATH_MAX) return false;
  std::size_t start = 0;
  while (start <= relative.size()) {
    const std::size_t end = std::min(relative.find('/', start), relative.size());
    if (end - start > NAME_MAX) return false;
    start = end + 1;
  }
  return true;
}

std::string ServedRoot::relative(const fs::path& inside) const {
  const fs::path part = inside.lexically_relative(root_);
  return part == "." ? std::string() : part.generic_string();
}

}  // namespace tendril::dashboard
