#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tendril {

// A view of one mapping inside an experiment's YAML configuration.
//
// Reads are typed and checked: a missing required key, or a value of the wrong type, raises
// Error naming the full key path (e.g. "env.params.n_elements") and the expected type. Every
// read marks its key as used; `reject_unknown()` then raises on the first key that nothing
// read, so a misspelt option is an error instead of being silently ignored.
class Config {
 public:
  // An empty mapping.
  Config();

  // At most kMaxFileBytes (experiment files are a few kilobytes; the bound keeps /dev/zero or
  // a runaway generator from exhausting memory); regular files and pipes only.
  static Config load_file(const std::filesystem::path& file);
  static constexpr std::size_t kMaxFileBytes = std::size_t{1} << 20;
  // The longest value `set` accepts (a command-line override).
  static constexpr std::size_t kMaxValueBytes = std::size_t{1} << 16;
  static Config parse(std::string_view yaml_text, std::string source = "<text>");

  bool has(std::string_view key) const;
  std::vector<std::string> keys() const;

  // Required values.
  template <typename T>
  T get(std::string_view key) const;
  // Optional values: `fallback` when the key is absent (a present key of the wrong type raises).
  // The fallback is recorded as the value used (see dump_resolved).
  template <typename T>
  T get_or(std::string_view key, const T& fallback) const;

  // An optional number: `fallback` when the key is absent, nothing when it holds `off_word`
  // ("none", "auto"); recorded like get_or's fallbacks.
  std::optional<double> get_optional(std::string_view key, const std::optional<double>& fallback,
                                     std::string_view off_word = "none") const;

  // A nested mapping; an absent key gives an empty mapping at that path.
  Config child(std::string_view key) const;
  // A sequence of mappings.
  std::vector<Config> children(std::string_view key) const;

  // Sets `dotted.key.path` to `value` parsed as a YAML scalar or flow sequence (the CLI's
  // `--set key=value`). Creates intermediate mappings as needed.
  void set(std::string_view dotted_path, std::string_view value);

  // Raises Error naming the first key below this view that no read has touched.
  void reject_unknown() const;

  // The key path of this view ("" for the root) and the file it came from.
  const std::string& path() const { return path_; }
  // Where `key` of this view is, for messages: "file.yaml: algo.batch_size".
  std::string where(std::string_view key) const;
  const std::string& source() const;

  // The whole document under this view as YAML text.
  std::string dump() const;
  // The whole document with every default that a read used (get_or's fallbacks) filled in:
  // what the program ran with, which reads back to the same values whatever the defaults of a
  // later version.
  std::string dump_resolved() const;
  // dump_resolved's document below this view as (key path relative to the view, value as YAML
  // flow text) pairs, one per value that is not a mapping ("drift.enabled", "true"), in document
  // order: the parameters a reader took, with the defaults it used.
  std::vector<std::pair<std::string, std::string>> resolved_entries() const;

 private:
  struct Shared;
  struct NodeHandle;
  Config(std::shared_ptr<Shared> shared, std::shared_ptr<NodeHandle> node, std::string path);
  std::string key_path(std::string_view key) const;

  std::shared_ptr<Shared> shared_;
  std::shared_ptr<NodeHandle> node_;
  std::string path_;
};

extern template double Config::get<double>(std::string_view) const;
extern template int64_t Config::get<int64_t>(std::string_view) const;
extern template int Config::get<int>(std::string_view) const;
extern template uint64_t Config::get<uint64_t>(std::string_view) const;
extern template bool Config::get<bool>(std::string_view) const;
extern template std::string Config::get<std::string>(std::string_view) const;
extern template std::vector<double> Config::get<std::vector<double>>(std::string_view) const;
extern template std::vector<int64_t> Config::get<std::vector<int64_t>>(std::string_view) const;
extern template std::vector<std::string> Config::get<std::vector<std::string>>(
    std::string_view) const;

extern template double Config::get_or<double>(std::string_view, const double&) const;
extern template int64_t Config::get_or<int64_t>(std::string_view, const int64_t&) const;
extern template int Config::get_or<int>(std::string_view, const int&) const;
extern template uint64_t Config::get_or<uint64_t>(std::string_view, const uint64_t&) const;
extern template bool Config::get_or<bool>(std::string_view, const bool&) const;
extern template std::string Config::get_or<std::string>(std::string_view, const std::string&) const;
extern template std::vector<double> Config::get_or<std::vector<double>>(
    std::string_view, const std::vector<double>&) const;
extern template std::vector<int64_t> Config::get_or<std::vector<int64_t>>(
    std::string_view, const std::vector<int64_t>&) const;
extern template std::vector<std::string> Config::get_or<std::vector<std::string>>(
    std::string_view, const std::vector<std::string>&) const;

}  // namespace tendril
