#include "io/obj_reader.hpp"

#include <cerrno>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <optional>
#include <fstream>
#include <string_view>

#include "base/decimal_range.hpp"
#include "base/error.hpp"
#include "base/input_file.hpp"
#include "base/utf8.hpp"
#include "forward/chunked_vector.hpp"
#include "graph/label.hpp"
#include "io/obj_lines.hpp"
#include "io/obj_plain_line.hpp"

namespace vern {

namespace {

// Statements of the OBJ format that carry nothing a labelled mesh needs.
constexpr std::string_view kIgnored[] = {
    "mtllib", "usemtl", "s",    "l",    "p",    "vp",       "cstype", "deg",     "bmat",      "step",
    "curv",   "curv2",  "surf", "parm", "trim", "hole",     "scrv",   "sp",      "end",       "con",
    "mg",     "lod",    "maplib", "usemap", "shadow_obj", "trace_obj", "ctech", "stech", "bevel",
    "c_interp", "d_interp"};

constexpr const char* kXyz[3] = {"x coordinate", "y coordinate", "z coordinate"};
constexpr const char* kUvw[3] = {"u coordinate", "v coordinate", "w coordinate"};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

struct Token {
  std::string_view text;
  std::size_t column = 0;  // 1-based
};

// Splits a line into whitespace-separated tokens, stopping at a comment.
void tokenize(std::string_view line, std::vector<Token>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i == line.size() || line[i] == '#') break;
    const std::size_t start = i;
    while (i < line.size() && !is_space(line[i])) ++i;
    out.push_back({line.substr(start, i - start), start + 1});
  }
}

// The rest of the line after the keyword, trimmed: names may hold spaces.
std::string_view rest_of_line(std::string_view line, const Token& keyword) {
  std::size_t b = keyword.column - 1 + keyword.text.size();
  std::size_t e = line.size();
  while (b < e && is_space(line[b])) ++b;
  const std::size_t hash = line.find('#', b);
  if (hash != std::string_view::npos) e = hash;
  while (e > b && is_space(line[e - 1])) --e;
  return line.substr(b, e - b);
}

// A run of faces under one `o` or `g` statement.
struct Segment {
  std::string name;
  std::uint32_t line = 0;
  std::uint32_t group = 0;  // ObjObject::group
};

// Reads statements and hands each object to `each_` as soon as it is
// complete. Vertices stay for the whole file (a face may use any vertex
// written before it); faces only until their object is handed over.
class Reader {
 public:
  Reader(const std::string& source, const ObjLimits& limits, const ObjObjectSink& each)
      : source_(source), limits_(limits), each_(each) {
    groups_.push_back({});  // faces before any `g`
  }

  void read_line(std::string_view line, std::uint32_t number) {
    line_ = number;
    // Nearly every line of a large file is a plain `v` or `f`: read those
    // without tokens; anything unusual is read again below, which also
    // reports any error.
    glm::dvec3 v;
    if (parse_plain_vertex(line, v)) {
      add_plain_vertex(v);
      return;
    }
    plain_indices_.clear();
    if (parse_plain_face(line, plain_indices_) && add_plain_face(plain_indices_.data(), plain_indices_.size())) return;
    if (const std::size_t nul = line.find('\0'); nul != std::string_view::npos) {
      error(nul + 1, "the file contains a NUL byte: it is not an OBJ text file",
            "give a Wavefront OBJ text file (for glTF or GLB examples use a .gltf/.glb path)");
    }
    tokenize(line, tokens_);
    if (tokens_.empty()) {
      read_comment(line);
      return;
    }
    const std::string_view key = tokens_[0].text;
    if (key == "v") {
      const glm::dvec3 p = read_vector(3, 3, "vertex", kXyz);
      check_magnitude(p);
      positions_.push_back(to_z_up(p, up_));
    } else if (key == "vn") {
      normals_.push_back(to_z_up(read_vector(3, 3, "normal", kXyz), up_));
    } else if (key == "vt") {
      const glm::dvec3 t = read_vector(1, 2, "texture coordinate", kUvw);
      uvs_.push_back({t.x, t.y});
    } else if (key == "f" || key == "fo") {
      read_face();
    } else if (key == "o") {
      start_object(name_after(line, tokens_[0]), number);
    } else if (key == "g") {
      // Once a file names parts with `o`, its groups (materials, smoothing)
      // no longer matter.
      ++groups_seen_;
      if (!any_object_)
        groups_.push_back({name_after(line, tokens_[0]), number, static_cast<std::uint32_t>(groups_seen_)});
    } else if (!is_ignored(key)) {
      if (!recognised_) {
        // Not quoted: a file that is not OBJ may be anything (a grammar's
        // @primitives may name a file of secrets), and binary data would
        // reach the terminal.
        error(tokens_[0].column,
              "this line is not an OBJ statement, nor is any line before it: this does not look like an OBJ file",
              "give a Wavefront OBJ text file: its lines start with v, vt, vn, f, o, g or #");
      }
      return;  // an extension some exporter added: nothing we need
    }
    recognised_ = true;
  }

  // A line as ObjLines gives it: one the read-ahead parsed goes straight
  // in (a face only if each index names a vertex above it); any other as
  // read_line takes it.
  void read_line(const ObjLine& l, std::string_view line, std::uint32_t number) {
    line_ = number;
    if (l.plain == PlainLine::Vertex) return add_plain_vertex(l.vertex);
    if (l.plain == PlainLine::Face && add_plain_face(l.indices, l.index_count)) return;
    read_line(line, number);
  }

  // Hands over what is still pending at the end of the file.
  void finish() {
    if (any_object_) {
      emit(object_, 0, face_sizes_.size());
      return;
    }
    // No `o` at all: `g` names the parts. A group's faces are consecutive.
    for (std::size_t begin = 0; begin < face_sizes_.size();) {
      std::size_t end = begin;
      while (end < face_sizes_.size() && face_group_[end] == face_group_[begin]) ++end;
      emit(groups_[face_group_[begin]], begin, end);
      begin = end;
    }
  }

 private:
  [[noreturn]] void error(std::size_t column, const std::string& message, const std::string& hint) const {
    fail(ErrorKind::Input, source_, {line_, static_cast<std::uint32_t>(column)}, message, hint);
  }

  // Files that name parts with `o` may also carry groups: then only `o`
  // counts, and faces before the first `o` are one unnamed object.
  void start_object(std::string name, std::uint32_t number) {
    if (any_object_) emit(object_, 0, face_sizes_.size());
    else emit({}, 0, face_sizes_.size());
    clear_faces();
    groups_.clear();
    any_object_ = true;
    object_ = {std::move(name), number, static_cast<std::uint32_t>(groups_seen_)};
    object_has_faces_ = false;
    part_faces_ = 0;
  }

  // The object of pending faces [begin, end), its vertices re-indexed from
  // 0 in order of first use; nothing when it has no faces.
  void emit(const Segment& segment, std::size_t begin, std::size_t end) {
    if (begin == end) return;
    object_out_.name = segment.name;
    object_out_.line = segment.line != 0 ? segment.line : face_line_[begin];
    object_out_.group = segment.group;
    Mesh& mesh = object_out_.mesh;
    mesh.positions.clear();
    mesh.normals.clear();
    mesh.uvs.clear();
    mesh.corners.clear();
    mesh.face_sizes.assign(face_sizes_.begin() + static_cast<std::ptrdiff_t>(begin),
                           face_sizes_.begin() + static_cast<std::ptrdiff_t>(end));
    position_map_.grow_to(positions_.size(), Mesh::kNone);
    normal_map_.grow_to(normals_.size(), Mesh::kNone);
    uv_map_.grow_to(uvs_.size(), Mesh::kNone);
    const std::size_t first_corner = face_corner_[begin];
    const std::size_t last_corner = end < face_corner_.size() ? face_corner_[end] : corners_.size();
    for (std::size_t c = first_corner; c < last_corner; ++c) {
      const Mesh::Corner& g = corners_[c];
      Mesh::Corner local;
      local.position = remap(g.position, position_map_, positions_, mesh.positions);
      local.normal = remap(g.normal, normal_map_, normals_, mesh.normals);
      local.uv = remap(g.uv, uv_map_, uvs_, mesh.uvs);
      mesh.corners.push_back(local);
    }
    // Reset only what this object touched: linear in the file's size.
    for (std::size_t c = first_corner; c < last_corner; ++c) {
      const Mesh::Corner& g = corners_[c];
      position_map_[g.position] = Mesh::kNone;
      if (g.normal != Mesh::kNone) normal_map_[g.normal] = Mesh::kNone;
      if (g.uv != Mesh::kNone) uv_map_[g.uv] = Mesh::kNone;
    }
    each_(object_out_);
  }

  void clear_faces() {
    corners_.clear();
    face_sizes_.clear();
    face_corner_.clear();
    face_group_.clear();
    face_line_.clear();
  }

  // An `o`/`g` name: it becomes a label in grammars and written files, so
  // it must be UTF-8 (see base/utf8.hpp).
  std::string name_after(std::string_view line, const Token& keyword) const {
    const std::string_view name = rest_of_line(line, keyword);
    if (const std::size_t bad = invalid_utf8_offset(name); bad != std::string_view::npos) {
      const std::size_t column = static_cast<std::size_t>(name.data() - line.data()) + bad + 1;
      char shown[8];
      std::snprintf(shown, sizeof shown, "0x%02X", static_cast<unsigned char>(name[bad]));
      error(column, std::string("the name is not UTF-8 text (byte ") + shown + ")",
            "export with UTF-8 names (Latin-1 and other code pages are not read), or rename the object in ASCII");
    }
    return std::string(name);
  }

  // Coordinates far beyond any building (often a float-overflow artefact
  // of the exporter) would turn extents into inf further on.
  void check_magnitude(const glm::dvec3& v) const {
    for (int i = 0; i < 3; ++i) {
      if (std::abs(v[i]) > kMaxObjCoordinate) {
        const Token& t = tokens_[static_cast<std::size_t>(i) + 1];
        error(t.column,
              "the " + std::string(kXyz[i]) + " '" + std::string(t.text) + "' is too large: coordinates beyond 1e12 " +
                  "cannot hold a millimetre",
              "the exporter wrote broken geometry, or the model is far from the origin: fix that vertex, or move the "
              "model near the origin in metres");
      }
    }
  }

  // A comment may declare the file's up axis (obj_reader.hpp): `# up y`
  // or `# up z` before the first vertex. The first line of a file an
  // earlier Vernacular wrote, without one, means z.
  void read_comment(std::string_view line) {
    const std::size_t hash = line.find('#');
    if (hash == std::string_view::npos) return;  // a blank line
    const std::string_view text = line.substr(hash + 1);
    if (line_ == 1 && (text.starts_with(" Written by Vernacular") || text.starts_with(" Vernacular built-in primitive"))) {
      up_ = UpAxis::Z;
      return;
    }
    // Most comments are not declarations (exporters' remarks, a 200 MB
    // file of them): a look at the first word before any tokenizing.
    const std::size_t first = text.find_first_not_of(" \t");
    if (first == std::string_view::npos || text.substr(first, 2) != "up") return;
    std::vector<Token>& words = comment_words_;
    tokenize(text, words);
    if (words.size() != 2 || words[0].text != "up") return;  // any other comment
    const std::size_t column = hash + 1 + words[1].column;
    const std::optional<UpAxis> up = parse_up_axis(words[1].text);
    if (!up) {
      error(column, "'# up " + std::string(words[1].text) + "' declares an up axis other than y or z",
            "write `# up y` (as Blender exports OBJ by default) or `# up z`, or remove the line");
    }
    if (positions_.size() + normals_.size() > 0) {
      error(hash + 1, "the up axis is declared after vertices, which were read with another",
            "move the `# up " + std::string(words[1].text) + "` line to the top of the file");
    }
    up_ = *up;
  }

  static bool is_ignored(std::string_view key) {
    for (std::string_view k : kIgnored) {
      if (k == key) return true;
    }
    return false;
  }

  double read_number(const Token& token, const char* what) const {
    std::string_view text = token.text;
    if (text.size() > 1 && text[0] == '+') text.remove_prefix(1);  // from_chars rejects '+'
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range) {
      error(token.column,
            "the " + std::string(what) + " '" + std::string(token.text) + "' is " +
                (decimal_underflows(text) ? "too small for a number: nearer to zero than any double (4.9e-324)"
                                          : "out of range for a number"),
            "the exporter wrote broken geometry: fix or delete that element");
    }
    if (ec != std::errc() || end != text.data() + text.size()) {
      error(token.column, "expected a number for the " + std::string(what) + ", found '" +
                              std::string(token.text) + "'",
            "write numbers like 1, -0.5 or 2.5e-3 (a '.' for the decimal point, no thousands separators)");
    }
    if (!std::isfinite(value)) {
      error(token.column, "the " + std::string(what) + " '" + std::string(token.text) + "' is not a finite number",
            "the exporter wrote broken geometry: fix or delete that element");
    }
    return value;
  }

  // The numbers after the keyword: at least `required`, the first `used` kept.
  glm::dvec3 read_vector(std::size_t required, std::size_t used, const char* what,
                         const char* const (&names)[3]) const {
    if (tokens_.size() - 1 < required) {
      error(tokens_[0].column,
            "a " + std::string(what) + " needs " + std::to_string(required) + " numbers, found " +
                std::to_string(tokens_.size() - 1),
            "write `" + std::string(tokens_[0].text) + "` followed by " + std::to_string(required) + " numbers on one line");
    }
    glm::dvec3 v(0.0);
    for (std::size_t i = 0; i < used && i + 1 < tokens_.size(); ++i) {
      v[static_cast<glm::length_t>(i)] = read_number(tokens_[i + 1], names[i]);
    }
    return v;
  }

  // One index of a face corner: 1-based, or negative counting back.
  std::uint32_t read_index(std::string_view text, std::size_t column, std::size_t count, const char* what,
                           const char* plural) const {
    long long i = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), i);
    if (ec == std::errc::result_out_of_range) {
      error(column, "the " + std::string(what) + " index '" + std::string(text) + "' is out of range",
            "a face may only use elements written before it; check the exporter's index offsets");
    }
    if (ec != std::errc() || end != text.data() + text.size()) {
      error(column, "expected a " + std::string(what) + " index, found '" + std::string(text) + "'",
            "face corners are v, v/vt, v//vn or v/vt/vn, with whole numbers counting from 1");
    }
    if (i == 0) {
      error(column, "a " + std::string(what) + " index of 0 is not valid",
            "OBJ indices count from 1 (or back from -1 for the latest)");
    }
    const long long resolved = i > 0 ? i - 1 : static_cast<long long>(count) + i;
    if (resolved < 0 || resolved >= static_cast<long long>(count)) {
      error(column,
            "the face refers to " + std::string(what) + " " + std::to_string(i) + ", but " +
                std::to_string(count) + " " + (count == 1 ? what : plural) + (count == 1 ? " is" : " are") +
                " defined above it",
            "a face may only use elements written before it; check the exporter's index offsets");
    }
    return static_cast<std::uint32_t>(resolved);
  }

  void read_face() {
    const std::size_t n = tokens_.size() - 1;
    if (n < 3) {
      error(tokens_[0].column, "a face needs at least 3 corners, found " + std::to_string(n),
            "write lines with `l` and points with `p`; they are not read as faces");
    }
    for (std::size_t k = 1; k <= n; ++k) {
      const Token& t = tokens_[k];
      const std::string_view text = t.text;
      const std::size_t s1 = text.find('/');
      const std::size_t s2 = s1 == std::string_view::npos ? s1 : text.find('/', s1 + 1);
      Mesh::Corner c;
      c.position = read_index(text.substr(0, s1), t.column, positions_.size(), "vertex", "vertices");
      if (s1 != std::string_view::npos) {
        const std::string_view vt = text.substr(s1 + 1, s2 == std::string_view::npos ? s2 : s2 - s1 - 1);
        if (!vt.empty()) c.uv = read_index(vt, t.column + s1 + 1, uvs_.size(), "texture coordinate", "texture coordinates");
        if (s2 != std::string_view::npos) {
          c.normal = read_index(text.substr(s2 + 1), t.column + s2 + 1, normals_.size(), "normal", "normals");
        }
      }
      corners_.push_back(c);
    }
    add_face(n);
  }

  // The face of the last n corners read: its bookkeeping and the limit.
  void add_face(std::size_t n) {
    // A segment's faces are consecutive, so a new segment shows as a change.
    if (!object_has_faces_) ++objects_with_faces_;
    object_has_faces_ = true;
    if (last_group_with_faces_ != groups_seen_) {
      ++groups_with_faces_;
      if (!any_object_) part_faces_ = 0;  // groups are the parts
    }
    last_group_with_faces_ = groups_seen_;
    if (++part_faces_ > limits_.max_faces && limits_.max_faces != 0) too_many_faces();
    face_corner_.push_back(static_cast<std::uint32_t>(corners_.size() - n));
    face_sizes_.push_back(static_cast<std::uint32_t>(n));
    if (!any_object_) face_group_.push_back(static_cast<std::uint32_t>(groups_.size() - 1));
    face_line_.push_back(line_);
    const std::size_t parts = any_object_ ? objects_with_faces_ : groups_with_faces_;
    if (limits_.max_objects != 0 && parts > limits_.max_objects) {
      fail(ErrorKind::Limit, source_, {line_, 1},
           "more than " + std::to_string(limits_.max_objects) + " objects with faces: reading stopped here",
           limits_.too_many_hint.empty() ? "split the file into smaller ones" : limits_.too_many_hint);
    }
  }

  [[noreturn, gnu::cold, gnu::noinline]] void too_many_faces() const {
    const Segment& part = any_object_ ? object_ : groups_.back();
    fail(ErrorKind::Limit, source_, {line_, 1},
         (part.name.empty() ? std::string("an unnamed object") : "'" + shown_name(part.name) + "'") +
             (part.line != 0 ? " (line " + std::to_string(part.line) + ")" : "") + " has more than " +
             std::to_string(limits_.max_faces) + " faces: reading stopped here",
         limits_.too_many_faces_hint.empty() ? "simplify the mesh" : limits_.too_many_faces_hint);
  }

  void add_plain_vertex(const glm::dvec3& v) {
    positions_.push_back(to_z_up(v, up_));
    recognised_ = true;
  }

  // The face of a plain line's indices (from 1) if each names a vertex
  // above it: added, true. Otherwise nothing is added.
  bool add_plain_face(const std::uint32_t* indices, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
      if (indices[k] > positions_.size()) return false;
    for (std::size_t k = 0; k < n; ++k) {
      Mesh::Corner c;
      c.position = indices[k] - 1;
      corners_.push_back(c);
    }
    add_face(n);
    recognised_ = true;
    return true;
  }

  template <class V>
  static std::uint32_t remap(std::uint32_t global, ChunkedVector<std::uint32_t>& map, const ChunkedVector<V>& from,
                             std::vector<V>& to) {
    if (global == Mesh::kNone) return Mesh::kNone;
    if (map[global] == Mesh::kNone) {
      map[global] = static_cast<std::uint32_t>(to.size());
      to.push_back(from[global]);
    }
    return map[global];
  }

  const std::string& source_;
  const ObjLimits& limits_;
  const ObjObjectSink& each_;
  UpAxis up_ = limits_.undeclared_up;  // the file's, once it declares one
  std::uint32_t line_ = 0;
  std::vector<Token> tokens_;
  std::vector<Token> comment_words_;  // a comment's, reused
  std::vector<std::uint32_t> plain_indices_;  // a plain face's, reused
  bool recognised_ = false;
  bool any_object_ = false;
  bool object_has_faces_ = false;  // the current `o` segment, or the faces before any `o`
  std::size_t part_faces_ = 0;      // faces of the current object (or group, without `o`)
  std::size_t objects_with_faces_ = 0;
  std::size_t groups_with_faces_ = 0;
  std::size_t groups_seen_ = 0;  // `g` statements so far
  std::size_t last_group_with_faces_ = std::numeric_limits<std::size_t>::max();

  ChunkedVector<glm::dvec3> positions_;
  ChunkedVector<glm::dvec3> normals_;
  ChunkedVector<glm::dvec2> uvs_;
  // The faces not yet handed over: of the current object, or before any
  // `o` all of them (they may yet turn out to be groups).
  std::vector<Mesh::Corner> corners_;  // global indices
  std::vector<std::uint32_t> face_sizes_;
  std::vector<std::uint32_t> face_corner_;  // each face's first corner in corners_
  std::vector<std::uint32_t> face_group_;   // segment in groups_
  std::vector<std::uint32_t> face_line_;
  Segment object_;               // the current `o`
  std::vector<Segment> groups_;  // only while no `o` has been seen
  // Reused from object to object.
  ObjObject object_out_;
  ChunkedVector<std::uint32_t> position_map_, normal_map_, uv_map_;
};

}  // namespace

void read_obj(std::istream& in, const std::string& source_name, const ObjLimits& limits, const ObjObjectSink& each,
              bool read_ahead) {
  Reader reader(source_name, limits, each);
  ObjLines lines(in, read_ahead);
  std::string joined;  // a statement continued over lines with a trailing '\'
  std::uint32_t number = 0;
  std::uint32_t statement_line = 0;
  ObjLine next;
  while (lines.next(next)) {
    std::string_view line = next.text;
    const bool last = next.last;
    ++number;
    // `got` counts the line break too, as std::istream::getline did.
    const std::size_t got = line.size() + (last ? 0 : 1);
    if (line.size() > kMaxObjLine || joined.size() + got > kMaxObjLine) {
      fail(ErrorKind::Input, source_name, {joined.empty() ? number : statement_line, 1},
           "a line longer than " + std::to_string(kMaxObjLine) + " bytes: this does not look like an OBJ text file",
           "give a Wavefront OBJ text file (for glTF or GLB examples use a .gltf/.glb path)");
    }
    if (number == 1 && line.starts_with("\xEF\xBB\xBF")) line.remove_prefix(3);  // UTF-8 byte order mark
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (joined.empty()) statement_line = number;
    if (!line.empty() && line.back() == '\\') {
      joined.append(line.substr(0, line.size() - 1));
      joined += ' ';
    } else if (!joined.empty()) {
      joined.append(line);
      reader.read_line(joined, statement_line);
      joined.clear();
    } else {
      reader.read_line(next, line, number);
    }
  }
  if (!joined.empty()) reader.read_line(joined, statement_line);
  if (lines.failed()) fail(ErrorKind::Io, source_name, {}, "cannot read: the stream failed", "check the file");
  reader.finish();
}

std::vector<ObjObject> read_obj(std::istream& in, const std::string& source_name, const ObjLimits& limits) {
  std::vector<ObjObject> objects;
  read_obj(in, source_name, limits, [&](const ObjObject& o) { objects.push_back(o); });
  return objects;
}

void read_obj_file(const std::filesystem::path& path, const ObjLimits& limits, const ObjObjectSink& each,
                   bool read_ahead) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    fail(ErrorKind::Io, path.string(), {}, "is a folder, not an OBJ file", "name an .obj file");
  }
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    fail(ErrorKind::Io, path.string(), {}, std::string("cannot open: ") + std::strerror(err),
         "check the path and the file's permissions");
  }
  read_obj(in, path.string(), limits, each, read_ahead);
}

std::vector<ObjObject> read_obj_file(const std::filesystem::path& path, const ObjLimits& limits) {
  std::vector<ObjObject> objects;
  read_obj_file(path, limits, [&](const ObjObject& o) { objects.push_back(o); });
  return objects;
}

}  // namespace vern
