#include "forward/obj_reader.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string_view>

#include "graph/error.hpp"
#include "graph/utf8.hpp"

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
};

class Reader {
 public:
  Reader(const std::string& source, const ObjLimits& limits) : source_(source), limits_(limits) {
    objects_.push_back({});  // faces before any `o`
    groups_.push_back({});   // faces before any `g`
  }

  void read_line(std::string_view line, std::uint32_t number) {
    line_ = number;
    if (const std::size_t nul = line.find('\0'); nul != std::string_view::npos) {
      error(nul + 1, "the file contains a NUL byte: it is not an OBJ text file",
            "give a Wavefront OBJ text file (for glTF or GLB examples use a .gltf/.glb path)");
    }
    tokenize(line, tokens_);
    if (tokens_.empty()) return;
    const std::string_view key = tokens_[0].text;
    if (key == "v") {
      positions_.push_back(read_vector(3, 3, "vertex", kXyz));
      check_magnitude(positions_.back());
    } else if (key == "vn") {
      normals_.push_back(read_vector(3, 3, "normal", kXyz));
    } else if (key == "vt") {
      const glm::dvec3 t = read_vector(1, 2, "texture coordinate", kUvw);
      uvs_.emplace_back(t.x, t.y);
    } else if (key == "f" || key == "fo") {
      read_face();
    } else if (key == "o") {
      any_object_ = true;
      objects_.push_back({name_after(line, tokens_[0]), number});
    } else if (key == "g") {
      groups_.push_back({name_after(line, tokens_[0]), number});
    } else if (!is_ignored(key)) {
      if (!recognised_) {
        // Binary data is named by its first byte, not echoed to the terminal.
        std::string shown = "'" + std::string(key.substr(0, 40)) + "'";
        for (const char c : key.substr(0, 40)) {
          const auto u = static_cast<unsigned char>(c);
          if (u < 0x20 || u >= 0x7F) {
            char byte[24];
            std::snprintf(byte, sizeof byte, "byte 0x%02X", static_cast<unsigned char>(key[0]));
            shown = byte;
            break;
          }
        }
        error(tokens_[0].column, shown + " is not an OBJ statement: this does not look like an OBJ file",
              "give a Wavefront OBJ text file: its lines start with v, vt, vn, f, o, g or #");
      }
      return;  // an extension some exporter added: nothing we need
    }
    recognised_ = true;
  }

  std::vector<ObjObject> finish() {
    // Files that name parts with `o` may also carry groups (materials,
    // smoothing): then only `o` counts. Otherwise `g` names the parts.
    const std::vector<Segment>& segments = any_object_ ? objects_ : groups_;
    const std::vector<std::uint32_t>& face_segment = any_object_ ? face_object_ : face_group_;

    // Faces of each segment, in file order (a counting sort).
    std::vector<std::uint32_t> first(segments.size() + 1, 0);
    for (std::uint32_t s : face_segment) ++first[s + 1];
    for (std::size_t s = 1; s < first.size(); ++s) first[s] += first[s - 1];
    std::vector<std::uint32_t> faces(face_segment.size());
    std::vector<std::uint32_t> corner_start(face_segment.size());
    {
      std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
      std::uint32_t corner = 0;
      for (std::uint32_t f = 0; f < face_segment.size(); ++f) {
        faces[next[face_segment[f]]++] = f;
        corner_start[f] = corner;
        corner += face_sizes_[f];
      }
    }

    std::vector<std::uint32_t> position_map(positions_.size(), Mesh::kNone);
    std::vector<std::uint32_t> normal_map(normals_.size(), Mesh::kNone);
    std::vector<std::uint32_t> uv_map(uvs_.size(), Mesh::kNone);
    std::vector<ObjObject> result;
    for (std::size_t s = 0; s < segments.size(); ++s) {
      if (first[s] == first[s + 1]) continue;
      ObjObject object;
      object.name = segments[s].name;
      object.line = segments[s].line != 0 ? segments[s].line : face_line_[faces[first[s]]];
      Mesh& mesh = object.mesh;
      for (std::uint32_t k = first[s]; k < first[s + 1]; ++k) {
        const std::uint32_t f = faces[k];
        mesh.face_sizes.push_back(face_sizes_[f]);
        for (std::uint32_t c = 0; c < face_sizes_[f]; ++c) {
          const Mesh::Corner& g = corners_[corner_start[f] + c];
          Mesh::Corner local;
          local.position = remap(g.position, position_map, positions_, mesh.positions);
          local.normal = remap(g.normal, normal_map, normals_, mesh.normals);
          local.uv = remap(g.uv, uv_map, uvs_, mesh.uvs);
          mesh.corners.push_back(local);
        }
      }
      // Reset only what this object touched: linear in the file's size.
      for (std::uint32_t k = first[s]; k < first[s + 1]; ++k) {
        const std::uint32_t f = faces[k];
        for (std::uint32_t c = 0; c < face_sizes_[f]; ++c) {
          const Mesh::Corner& g = corners_[corner_start[f] + c];
          position_map[g.position] = Mesh::kNone;
          if (g.normal != Mesh::kNone) normal_map[g.normal] = Mesh::kNone;
          if (g.uv != Mesh::kNone) uv_map[g.uv] = Mesh::kNone;
        }
      }
      result.push_back(std::move(object));
    }
    return result;
  }

 private:
  [[noreturn]] void error(std::size_t column, const std::string& message, const std::string& hint) const {
    fail(ErrorKind::Input, source_, {line_, static_cast<std::uint32_t>(column)}, message, hint);
  }

  // An `o`/`g` name: it becomes a label in grammars and written files, so
  // it must be UTF-8 (see graph/utf8.hpp).
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
      error(token.column, "the " + std::string(what) + " '" + std::string(token.text) + "' is out of range for a number",
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
    const auto object = static_cast<std::uint32_t>(objects_.size() - 1);
    const auto group = static_cast<std::uint32_t>(groups_.size() - 1);
    // A segment's faces are consecutive, so a new segment shows as a change.
    if (face_object_.empty() || face_object_.back() != object) ++objects_with_faces_;
    if (face_group_.empty() || face_group_.back() != group) ++groups_with_faces_;
    face_sizes_.push_back(static_cast<std::uint32_t>(n));
    face_object_.push_back(object);
    face_group_.push_back(group);
    face_line_.push_back(line_);
    const std::size_t parts = any_object_ ? objects_with_faces_ : groups_with_faces_;
    if (limits_.max_objects != 0 && parts > limits_.max_objects) {
      fail(ErrorKind::Limit, source_, {line_, 1},
           "more than " + std::to_string(limits_.max_objects) + " objects with faces: reading stopped here",
           limits_.too_many_hint.empty() ? "split the file into smaller ones" : limits_.too_many_hint);
    }
  }

  template <class V>
  static std::uint32_t remap(std::uint32_t global, std::vector<std::uint32_t>& map, const std::vector<V>& from,
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
  std::uint32_t line_ = 0;
  std::vector<Token> tokens_;
  bool recognised_ = false;
  bool any_object_ = false;
  std::size_t objects_with_faces_ = 0;
  std::size_t groups_with_faces_ = 0;

  std::vector<glm::dvec3> positions_;
  std::vector<glm::dvec3> normals_;
  std::vector<glm::dvec2> uvs_;
  std::vector<Mesh::Corner> corners_;  // global indices
  std::vector<std::uint32_t> face_sizes_;
  std::vector<std::uint32_t> face_object_;  // segment in objects_
  std::vector<std::uint32_t> face_group_;   // segment in groups_
  std::vector<std::uint32_t> face_line_;
  std::vector<Segment> objects_;
  std::vector<Segment> groups_;
};

}  // namespace

std::vector<ObjObject> read_obj(std::istream& in, const std::string& source_name, const ObjLimits& limits) {
  Reader reader(source_name, limits);
  // Lines are read into one fixed buffer: a file without line breaks (or
  // binary data) costs kMaxObjLine bytes, not its own size.
  std::vector<char> buffer(kMaxObjLine + 1);
  std::string joined;  // a statement continued over lines with a trailing '\'
  std::uint32_t number = 0;
  std::uint32_t statement_line = 0;
  while (true) {
    in.getline(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto got = static_cast<std::size_t>(in.gcount());
    if (in.bad()) break;
    // A full buffer without a line break: the line is longer than allowed.
    const bool too_long = in.fail() && !in.eof();
    if (got == 0 && in.eof()) break;
    ++number;
    if (too_long || joined.size() + got > kMaxObjLine) {
      fail(ErrorKind::Input, source_name, {joined.empty() ? number : statement_line, 1},
           "a line longer than " + std::to_string(kMaxObjLine) + " bytes: this does not look like an OBJ text file",
           "give a Wavefront OBJ text file (for glTF or GLB examples use a .gltf/.glb path)");
    }
    const bool last = in.eof();  // no line break was consumed
    std::string_view line(buffer.data(), got - (last ? 0 : 1));
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
      reader.read_line(line, number);
    }
    if (last) break;
  }
  if (!joined.empty()) reader.read_line(joined, statement_line);
  if (in.bad()) fail(ErrorKind::Io, source_name, {}, "cannot read: the stream failed", "check the file");
  return reader.finish();
}

std::vector<ObjObject> read_obj_file(const std::filesystem::path& path, const ObjLimits& limits) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) {
    fail(ErrorKind::Io, path.string(), {}, "is a folder, not an OBJ file", "name an .obj file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    fail(ErrorKind::Io, path.string(), {}, std::string("cannot open: ") + std::strerror(err),
         "check the path and the file's permissions");
  }
  return read_obj(in, path.string(), limits);
}

}  // namespace vern
