#include "tendril/core/config.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/yaml.h>

#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "tendril/core/error.hpp"

namespace tendril {

struct Config::Shared {
  std::string source;
  std::set<std::string> used;                             // key paths that a read touched
  YAML::Node root;                                        // the whole document
  YAML::Node defaults = YAML::Node(YAML::NodeType::Map);  // fallbacks get_or used, by path
};

struct Config::NodeHandle {
  YAML::Node node;
};

namespace {

// A value as messages quote it: long ones (a runaway file, a huge override) cut short.
std::string clipped(std::string_view text) {
  constexpr std::size_t kShown = 60;
  if (text.size() <= kShown) return std::string(text);
  return std::string(text.substr(0, kShown)) + "... (" + std::to_string(text.size()) + " bytes)";
}

std::string type_name(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "null";
    case YAML::NodeType::Scalar:
      return "'" + clipped(node.Scalar()) + "'";
    case YAML::NodeType::Sequence:
      return "a sequence";
    case YAML::NodeType::Map:
      return "a mapping";
    default:
      return "nothing";
  }
}

[[noreturn]] void wrong_type(const std::string& where, const char* expected,
                             const YAML::Node& node) {
  throw Error(std::string("expected ") + expected + ", got " + type_name(node), where);
}

template <typename T>
T convert_scalar(const YAML::Node& node, const std::string& where, const char* expected) {
  if (!node.IsScalar()) wrong_type(where, expected, node);
  try {
    return node.as<T>();
  } catch (const YAML::Exception&) {
    wrong_type(where, expected, node);
  }
}

template <typename T>
T convert(const YAML::Node& node, const std::string& where);

template <>
double convert<double>(const YAML::Node& node, const std::string& where) {
  const double value = convert_scalar<double>(node, where, "a number");
  if (!std::isfinite(value)) throw Error("expected a finite number, got " + type_name(node), where);
  return value;
}
template <>
int64_t convert<int64_t>(const YAML::Node& node, const std::string& where) {
  if (node.IsScalar()) {
    // Accept integral values written in floating-point form (1e6, 2000000.0).
    try {
      return node.as<int64_t>();
    } catch (const YAML::Exception&) {
      double value = 0;
      if (YAML::convert<double>::decode(node, value) && std::isfinite(value) &&
          value == std::floor(value) && std::abs(value) < 9.0e18) {
        return static_cast<int64_t>(value);
      }
    }
  }
  wrong_type(where, "an integer", node);
}
template <>
int convert<int>(const YAML::Node& node, const std::string& where) {
  const int64_t value = convert<int64_t>(node, where);
  if (value < INT32_MIN || value > INT32_MAX) wrong_type(where, "a 32-bit integer", node);
  return static_cast<int>(value);
}
template <>
uint64_t convert<uint64_t>(const YAML::Node& node, const std::string& where) {
  const int64_t value = convert<int64_t>(node, where);
  if (value < 0) wrong_type(where, "a non-negative integer", node);
  return static_cast<uint64_t>(value);
}
template <>
bool convert<bool>(const YAML::Node& node, const std::string& where) {
  return convert_scalar<bool>(node, where, "true or false");
}
template <>
std::string convert<std::string>(const YAML::Node& node, const std::string& where) {
  return convert_scalar<std::string>(node, where, "a string");
}

template <typename T>
std::vector<T> convert_sequence(const YAML::Node& node, const std::string& where,
                                const char* expected) {
  if (!node.IsSequence()) wrong_type(where, expected, node);
  std::vector<T> values;
  values.reserve(node.size());
  for (std::size_t i = 0; i < node.size(); ++i) {
    values.push_back(convert<T>(node[i], where + "[" + std::to_string(i) + "]"));
  }
  return values;
}
template <>
std::vector<double> convert<std::vector<double>>(const YAML::Node& node, const std::string& where) {
  return convert_sequence<double>(node, where, "a sequence of numbers");
}
template <>
std::vector<int64_t> convert<std::vector<int64_t>>(const YAML::Node& node,
                                                   const std::string& where) {
  return convert_sequence<int64_t>(node, where, "a sequence of integers");
}
template <>
std::vector<std::string> convert<std::vector<std::string>>(const YAML::Node& node,
                                                           const std::string& where) {
  return convert_sequence<std::string>(node, where, "a sequence of strings");
}

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

void find_unused(const YAML::Node& node, const std::string& path, const std::set<std::string>& used,
                 const std::string& source) {
  if (!node.IsMap()) return;
  for (const auto& entry : node) {
    const std::string key_path = join(path, entry.first.as<std::string>());
    if (!used.count(key_path)) throw Error("unknown key '" + key_path + "'", source);
    find_unused(entry.second, key_path, used, source);
  }
}

// Every mapping key in `node` must be a scalar (a name): YAML also allows sequences and mappings
// as keys (`{[1, 2]: x}`), which no config key path can name.
void require_scalar_keys(const YAML::Node& node, const std::string& where) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      if (!entry.first.IsScalar()) {
        const YAML::Mark mark = entry.first.Mark();
        throw Error("a key must be a name, got " + type_name(entry.first) +
                        (mark.is_null() ? std::string()
                                        : " at line " + std::to_string(mark.line + 1) +
                                              ", column " + std::to_string(mark.column + 1)),
                    where);
      }
      require_scalar_keys(entry.second, where);
    }
  } else if (node.IsSequence()) {
    for (const auto& item : node) require_scalar_keys(item, where);
  }
}

YAML::Node parse_yaml(std::string_view text, const std::string& source) {
  try {
    YAML::Node root = YAML::Load(std::string(text));
    if (root.IsNull()) return YAML::Node(YAML::NodeType::Map);
    if (!root.IsMap())
      throw Error("the document must be a mapping, got " + type_name(root), source);
    require_scalar_keys(root, source);
    return root;
  } catch (const YAML::DeepRecursion& e) {
    // yaml-cpp stops at a fixed depth with a message ("bad file") that names no cause.
    throw Error("lists or mappings nested too deeply for the YAML parser (its depth limit " +
                    std::to_string(e.depth()) + " reached at line " +
                    std::to_string(e.mark.line + 1) + ", column " +
                    std::to_string(e.mark.column + 1) + ")",
                source);
  } catch (const YAML::ParserException& e) {
    throw Error("malformed YAML at line " + std::to_string(e.mark.line + 1) + ", column " +
                    std::to_string(e.mark.column + 1) + ": " + e.msg,
                source);
  }
}

}  // namespace

Config::Config() {
  YAML::Node root(YAML::NodeType::Map);
  shared_ = std::make_shared<Shared>(Shared{"<empty>", {}, root});
  node_ = std::make_shared<NodeHandle>(NodeHandle{root});
}

Config::Config(std::shared_ptr<Shared> shared, std::shared_ptr<NodeHandle> node, std::string path)
    : shared_(std::move(shared)), node_(std::move(node)), path_(std::move(path)) {}

Config Config::load_file(const std::filesystem::path& file) {
  std::error_code error;
  const auto status = std::filesystem::status(file, error);
  if (std::filesystem::is_directory(status)) {
    throw Error("is a directory, not a config file", file.string());
  }
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
      !std::filesystem::is_fifo(status)) {
    throw Error("not a regular file", file.string());
  }
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw Error("cannot open config file", file.string());
  std::string text;
  char chunk[65536];
  while (stream.read(chunk, sizeof chunk) || stream.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(stream.gcount()));
    if (text.size() > kMaxFileBytes) {
      throw Error(
          "larger than " + std::to_string(kMaxFileBytes >> 20) + " MiB; not an experiment file",
          file.string());
    }
  }
  if (stream.bad()) throw Error("cannot read config file", file.string());
  return parse(text, file.string());
}

Config Config::parse(std::string_view yaml_text, std::string source) {
  YAML::Node root = parse_yaml(yaml_text, source);
  return Config(std::make_shared<Shared>(Shared{std::move(source), {}, root}),
                std::make_shared<NodeHandle>(NodeHandle{root}), "");
}

std::string Config::key_path(std::string_view key) const { return join(path_, key); }

const std::string& Config::source() const { return shared_->source; }

bool Config::has(std::string_view key) const {
  return node_->node.IsMap() && static_cast<bool>(node_->node[std::string(key)]);
}

std::vector<std::string> Config::keys() const {
  std::vector<std::string> names;
  if (!node_->node.IsMap()) return names;
  for (const auto& entry : node_->node) names.push_back(entry.first.as<std::string>());
  return names;
}

template <typename T>
T Config::get(std::string_view key) const {
  const std::string where = key_path(key);
  if (!has(key)) throw Error("missing required key '" + where + "'", shared_->source);
  shared_->used.insert(where);
  return convert<T>(node_->node[std::string(key)], shared_->source + ": " + where);
}

template double Config::get<double>(std::string_view) const;
template int64_t Config::get<int64_t>(std::string_view) const;
template int Config::get<int>(std::string_view) const;
template uint64_t Config::get<uint64_t>(std::string_view) const;
template bool Config::get<bool>(std::string_view) const;
template std::string Config::get<std::string>(std::string_view) const;
template std::vector<double> Config::get<std::vector<double>>(std::string_view) const;
template std::vector<int64_t> Config::get<std::vector<int64_t>>(std::string_view) const;
template std::vector<std::string> Config::get<std::vector<std::string>>(std::string_view) const;

namespace {

// Sets `dotted` (a key path such as "algo.policy.net_arch") in `map` to `value`, creating the
// mappings on the way. Paths through sequences ("grid[0].key") are not recorded.
template <typename T>
void set_path(YAML::Node map, const std::string& dotted, const T& value) {
  if (dotted.find('[') != std::string::npos) return;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted.find('.', start);
    const std::string part = dotted.substr(start, dot - start);
    if (dot == std::string::npos) {
      map[part] = value;
      return;
    }
    if (!map[part] || !map[part].IsMap()) map[part] = YAML::Node(YAML::NodeType::Map);
    map.reset(map[part]);
    start = dot + 1;
  }
}

// `base` with every entry of `overlay` that `base` lacks, recursively.
void fill_missing(YAML::Node base, const YAML::Node& overlay) {
  for (const auto& entry : overlay) {
    const std::string key = entry.first.as<std::string>();
    YAML::Node existing = base[key];
    if (!existing) {
      base[key] = YAML::Clone(entry.second);
    } else if (existing.IsMap() && entry.second.IsMap()) {
      fill_missing(existing, entry.second);
    }
  }
}

}  // namespace

template <typename T>
T Config::get_or(std::string_view key, const T& fallback) const {
  if (has(key)) return get<T>(key);
  set_path(shared_->defaults, key_path(key), fallback);
  return fallback;
}

template double Config::get_or<double>(std::string_view, const double&) const;
template int64_t Config::get_or<int64_t>(std::string_view, const int64_t&) const;
template int Config::get_or<int>(std::string_view, const int&) const;
template uint64_t Config::get_or<uint64_t>(std::string_view, const uint64_t&) const;
template bool Config::get_or<bool>(std::string_view, const bool&) const;
template std::string Config::get_or<std::string>(std::string_view, const std::string&) const;
template std::vector<double> Config::get_or<std::vector<double>>(std::string_view,
                                                                 const std::vector<double>&) const;
template std::vector<int64_t> Config::get_or<std::vector<int64_t>>(
    std::string_view, const std::vector<int64_t>&) const;
template std::vector<std::string> Config::get_or<std::vector<std::string>>(
    std::string_view, const std::vector<std::string>&) const;

std::optional<double> Config::get_optional(std::string_view key,
                                           const std::optional<double>& fallback,
                                           std::string_view off_word) const {
  if (!has(key)) {
    if (fallback) {
      set_path(shared_->defaults, key_path(key), *fallback);
    } else {
      set_path(shared_->defaults, key_path(key), std::string(off_word));
    }
    return fallback;
  }
  if (get<std::string>(key) == off_word) return std::nullopt;
  return get<double>(key);
}

namespace {

// The document `root` with the defaults a read used filled in, below the view at `path`.
YAML::Node resolved_view(const YAML::Node& root, const YAML::Node& defaults,
                         const std::string& path) {
  YAML::Node resolved = YAML::Clone(root);
  if (!resolved.IsMap()) resolved = YAML::Node(YAML::NodeType::Map);
  fill_missing(resolved, defaults);
  // This view's part of it.
  YAML::Node view = resolved;
  if (!path.empty() && path.find('[') == std::string::npos) {
    std::size_t start = 0;
    while (view && start <= path.size()) {
      const std::size_t dot = path.find('.', start);
      view.reset(view[path.substr(start, dot - start)]);
      if (dot == std::string::npos) break;
      start = dot + 1;
    }
  }
  return view ? view : YAML::Node(YAML::NodeType::Map);
}

}  // namespace

std::string Config::where(std::string_view key) const {
  return shared_->source + ": " + key_path(key);
}

Config Config::child(std::string_view key) const {
  const std::string where = key_path(key);
  shared_->used.insert(where);
  if (!has(key)) {
    return Config(shared_,
                  std::make_shared<NodeHandle>(NodeHandle{YAML::Node(YAML::NodeType::Map)}), where);
  }
  YAML::Node node = node_->node[std::string(key)];
  if (!node.IsMap()) wrong_type(shared_->source + ": " + where, "a mapping", node);
  return Config(shared_, std::make_shared<NodeHandle>(NodeHandle{node}), where);
}

std::vector<Config> Config::children(std::string_view key) const {
  const std::string where = key_path(key);
  std::vector<Config> result;
  if (!has(key)) return result;
  shared_->used.insert(where);
  YAML::Node node = node_->node[std::string(key)];
  if (!node.IsSequence())
    wrong_type(shared_->source + ": " + where, "a sequence of mappings", node);
  for (std::size_t i = 0; i < node.size(); ++i) {
    const std::string item_path = where + "[" + std::to_string(i) + "]";
    if (!node[i].IsMap()) wrong_type(shared_->source + ": " + item_path, "a mapping", node[i]);
    result.push_back(Config(shared_, std::make_shared<NodeHandle>(NodeHandle{node[i]}), item_path));
  }
  return result;
}

void Config::set(std::string_view dotted_path, std::string_view value) {
  const std::string where = "--set " + std::string(dotted_path);
  if (dotted_path.empty()) throw Error("empty key", where);
  if (value.size() > kMaxValueBytes) {
    throw Error("value of " + std::to_string(value.size()) + " bytes; at most " +
                    std::to_string(kMaxValueBytes) + " are accepted",
                where);
  }
  YAML::Node parsed;
  try {
    parsed = YAML::Load(std::string(value));
  } catch (const YAML::ParserException& e) {
    throw Error("malformed value '" + clipped(value) + "': " + e.msg, where);
  }
  require_scalar_keys(parsed, where);
  YAML::Node node = node_->node;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = dotted_path.find('.', start);
    const std::string part(dotted_path.substr(start, dot - start));
    if (part.empty()) throw Error("empty component in key path", where);
    if (dot == std::string_view::npos) {
      node[part] = parsed;
      return;
    }
    YAML::Node next = node[part];
    if (!next) {
      node[part] = YAML::Node(YAML::NodeType::Map);
    } else if (!next.IsMap()) {
      throw Error("'" + part + "' is not a mapping", where);
    }
    node.reset(node[part]);
    start = dot + 1;
  }
}

void Config::reject_unknown() const {
  find_unused(node_->node, path_, shared_->used, shared_->source);
}

std::string Config::dump() const {
  YAML::Emitter out;
  out << node_->node;
  return std::string(out.c_str()) + "\n";
}

std::string Config::dump_resolved() const {
  YAML::Emitter out;
  out << resolved_view(shared_->root, shared_->defaults, path_);
  return std::string(out.c_str()) + "\n";
}

namespace {

// A scalar that reads fully as a decimal number, to 15 significant digits: yaml-cpp writes the
// 17 of a double (0.14999999999999999 for 0.15, 29.999999999999996 for a default converted from
// radians), more than any parameter means. Other scalars unchanged.
YAML::Node readable_numbers(const YAML::Node& node) {
  if (node.IsSequence()) {
    YAML::Node copy(YAML::NodeType::Sequence);
    for (const auto& item : node) copy.push_back(readable_numbers(item));
    return copy;
  }
  if (!node.IsScalar()) return node;
  const std::string& text = node.Scalar();
  if (text.find_first_of(".eE") == std::string::npos) return node;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return node;
  char buffer[32];
  const auto written =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 15);
  return YAML::Node(std::string(buffer, written.ptr));
}

void flatten(const YAML::Node& node, const std::string& path,
             std::vector<std::pair<std::string, std::string>>& entries) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      flatten(entry.second, join(path, entry.first.as<std::string>()), entries);
    }
    return;
  }
  YAML::Emitter out;
  out.SetSeqFormat(YAML::Flow);
  out.SetMapFormat(YAML::Flow);
  out << readable_numbers(node);
  entries.emplace_back(path, out.c_str());
}

}  // namespace

std::vector<std::pair<std::string, std::string>> Config::resolved_entries() const {
  std::vector<std::pair<std::string, std::string>> entries;
  const YAML::Node view = resolved_view(shared_->root, shared_->defaults, path_);
  if (view.IsMap()) flatten(view, "", entries);
  return entries;
}

}  // namespace tendril
