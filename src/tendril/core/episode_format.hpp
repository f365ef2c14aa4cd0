#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "tendril/core/scene.hpp"

// The pieces of the episode file format (docs/episode_format.md) that its writer and reader
// share: the records' framing, the layout record, and how each Scene primitive becomes float32s.
namespace tendril::episode_format {

inline constexpr std::string_view kMagic = "tendril-episode\n";  // 16 bytes
inline constexpr uint32_t kVersion = 1;
// Record framing: tag (1 byte), payload length (u32), payload, CRC-32 of all three.
inline constexpr std::size_t kRecordOverhead = 1 + 4 + 4;

enum class Tag : uint8_t { kHeader = 'H', kLayout = 'L', kFrame = 'F', kEnd = 'E' };

// Primitive kinds in the order a Scene lists them; a frame's primitives follow this order.
enum class Kind : uint8_t {
  kRod = 1,
  kSphere = 2,
  kCylinder = 3,
  kBox = 4,
  kPlane = 5,
  kLattice = 6,
  kPath = 7
};

// What stays fixed while a layout holds: a primitive's kind, role and sizes (a lattice's springs
// too). A frame whose scene has another layout starts a new layout record.
struct Primitive {
  Kind kind = Kind::kSphere;
  std::string role;
  uint32_t points = 0;                                 // rod nodes, lattice nodes, path points
  uint32_t radii = 0;                                  // rod radii: 1 or points − 1
  bool capped = false;                                 // cylinder
  std::vector<std::pair<uint32_t, uint32_t>> springs;  // lattice

  std::size_t float_count() const;  // of its per-frame data
  bool operator==(const Primitive&) const = default;
};

struct Layout {
  uint32_t action_size = 0;
  std::vector<std::string> info_names;
  std::vector<std::string> value_names;
  std::vector<Primitive> primitives;
  bool operator==(const Layout&) const = default;
};

// The layout of `scene` with these info names.
Layout layout_of(const Scene& scene, std::vector<std::string> info_names, uint32_t action_size);

// Each primitive's per-frame numbers as float32, in the layout's order.
std::vector<std::vector<float>> primitive_data(const Scene& scene);

// The primitives of a layout from their per-frame numbers (the reader's inverse of the above).
void fill_scene(const Layout& layout, const std::vector<std::vector<float>>& data, Scene& scene);

// Little-endian appending of the format's scalar types.
class Bytes {
 public:
  void u8(uint8_t value) { buffer_.push_back(static_cast<char>(value)); }
  void u32(uint32_t value) { raw(&value, sizeof value); }
  void f32(float value) { raw(&value, sizeof value); }
  void f64(double value) { raw(&value, sizeof value); }
  void text(std::string_view value);  // u32 byte length, then UTF-8 bytes
  void raw(const void* data, std::size_t size);
  const std::string& str() const { return buffer_; }

 private:
  std::string buffer_;
};

// Bounds-checked reading of a record's payload; reading past its end raises Error naming `where`.
class Cursor {
 public:
  Cursor(std::string_view bytes, std::string where) : bytes_(bytes), where_(std::move(where)) {}
  uint8_t u8();
  uint32_t u32();
  float f32();
  double f64();
  std::string text();
  // A count of items each at least `item_bytes` long, checked against the bytes left.
  uint32_t count(std::size_t item_bytes);
  bool done() const { return position_ == bytes_.size(); }
  // Raises Error unless `size` more bytes are left: a check before allocating room for them.
  void expect(std::size_t size) const;
  // Passes over `size` bytes (Error when fewer are left).
  void skip(std::size_t size);

 private:
  void raw(void* data, std::size_t size);
  std::string_view bytes_;
  std::size_t position_ = 0;
  std::string where_;
};

void encode_layout(const Layout& layout, Bytes& out);
Layout decode_layout(Cursor& in);

}  // namespace tendril::episode_format
