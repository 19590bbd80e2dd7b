#include "layout.hpp"

#include <array>

namespace vern::fuzz {

namespace {

constexpr std::array<double, 8> kUnits{1, 0.5, 0.25, 0.1, 3, 0.001, 1000, 0.3};
constexpr int kMaxDepth = 3;
constexpr std::size_t kMaxParts = 48;
constexpr unsigned kMinPeeled = 257, kPeeledRange = 128;

class ByteReader {
 public:
  explicit ByteReader(Bytes bytes) : bytes_(bytes) {}
  // Past the end every byte reads as 0: short inputs are layouts too.
  unsigned next() { return pos_ < bytes_.size() ? bytes_[pos_++] : 0u; }

 private:
  Bytes bytes_;
  std::size_t pos_ = 0;
};

std::string label_of(unsigned byte) { return std::string(1, static_cast<char>('a' + byte % 6)); }

void add_box(Example& ex, const std::string& label, glm::dvec3 min, glm::dvec3 max) {
  LabelledBox b;
  b.label = label;
  b.min = min;
  b.max = max;
  const auto index = static_cast<std::uint32_t>(ex.boxes.size());
  b.object = label + "." + std::to_string(index);
  b.line = index + 1;  // as if each part were one `o` line of an OBJ file
  b.mesh = index;      // no meshes: infer falls back to the library's box
  ex.boxes.push_back(std::move(b));
}

void free_boxes(ByteReader& in, unsigned mode, Example& ex) {
  const unsigned count = 1 + (mode >> 1) % 16;
  for (unsigned i = 0; i < count; ++i) {
    const std::string label = label_of(in.next());
    glm::dvec3 min, size;
    for (int a = 0; a < 3; ++a) min[a] = in.next() % 32;
    for (int a = 0; a < 3; ++a) size[a] = in.next() % 16;
    add_box(ex, label, min, min + size);
  }
}

void cut(ByteReader& in, glm::dvec3 min, glm::dvec3 max, int depth, Example& ex) {
  const unsigned byte = in.next();
  const unsigned kind = (depth >= kMaxDepth || ex.boxes.size() >= kMaxParts) ? 0 : byte % 4;
  if (kind == 0) {
    add_box(ex, label_of(byte >> 2), min, max);
    return;
  }
  if (kind == 1) return;  // empty space
  const int axis = static_cast<int>((byte >> 2) % 3);
  const unsigned parts = 2 + (byte >> 4) % 3;
  std::array<double, 4> weights{};
  double total = 0;
  for (unsigned i = 0; i < parts; ++i) total += weights[i] = 1 + in.next() % 4;
  double from = min[axis], done = 0;
  for (unsigned i = 0; i < parts; ++i) {
    done += weights[i];
    glm::dvec3 lo = min, hi = max;
    lo[axis] = from;
    hi[axis] = i + 1 == parts ? max[axis] : min[axis] + (max[axis] - min[axis]) * done / total;
    cut(in, lo, hi, depth + 1, ex);
    from = hi[axis];
  }
}

// A cut tree deeper than the grammar reader nests text (256): each part
// peels a slab one unit thick off the rest, along the axis its byte names
// (the next with room, where that one has none), and the core left is the
// last part.
void peeled(ByteReader& in, Example& ex) {
  const unsigned slabs = kMinPeeled + in.next() % kPeeledRange;
  glm::dvec3 min(0.0), max(static_cast<double>(slabs + 1));
  for (unsigned i = 0; i < slabs; ++i) {
    const unsigned byte = in.next();
    int axis = static_cast<int>(byte % 3);
    while (max[axis] - min[axis] <= 1) axis = (axis + 1) % 3;
    glm::dvec3 top = max;
    top[axis] = min[axis] + 1;
    add_box(ex, label_of(byte >> 2), min, top);
    min[axis] += 1;
  }
  add_box(ex, label_of(in.next()), min, max);
}

}  // namespace

Layout decode_layout(Bytes input) {
  ByteReader in(input);
  const unsigned header = in.next();
  const unsigned count = (header & 3u) == 3u ? 1 : 1 + (header & 3u);
  const double unit = kUnits[(header >> 2) & 7u];
  const bool single_precision = (header & 0x20u) != 0;
  const bool offset = (header & 0x40u) != 0;

  Layout layout;
  for (unsigned e = 0; e < count; ++e) {
    Example ex;
    ex.source = "layout" + std::to_string(e) + ".obj";
    const unsigned mode = in.next();
    if ((mode & 0xC1u) == 0xC1u) {
      peeled(in, ex);
    } else if (mode & 1u) {
      glm::dvec3 size;
      for (int a = 0; a < 3; ++a) size[a] = 1 + in.next() % 24;
      cut(in, glm::dvec3(0.0), size, 0, ex);
    } else {
      layout.valid_by_construction = false;
      free_boxes(in, mode, ex);
    }
    // Grid units to metres, the example's corner at the origin or moved
    // from it by a fraction of its own size: 32-bit rounding then stays
    // well within the default tolerance (1e-6 of the largest extent).
    update_bounds(ex);
    const glm::dvec3 corner = ex.min;
    const glm::dvec3 shift =
        offset ? (ex.max - ex.min) * glm::dvec3(0.5, -0.25, 0.125) * double(e + 1) : glm::dvec3(0.0);
    for (LabelledBox& b : ex.boxes) {
      for (glm::dvec3* p : {&b.min, &b.max}) {
        *p = (*p - corner + shift) * unit;
        if (single_precision) *p = glm::dvec3(glm::vec3(*p));
      }
    }
    update_bounds(ex);
    layout.examples.push_back(std::move(ex));
  }
  return layout;
}

}  // namespace vern::fuzz
