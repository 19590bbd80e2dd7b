#include "forward/obj_reader.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string_view>

#include "graph/error.hpp"

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
  explicit Reader(const std::string& source) : source_(source) {
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
    } else if (key == "vn") {
      normals_.push_back(read_vector(3, 3, "normal", kXyz));
    } else if (key == "vt") {
      const glm::dvec3 t = read_vector(1, 2, "texture coordinate", kUvw);
      uvs_.emplace_back(t.x, t.y);
    } else if (key == "f" || key == "fo") {
      read_face();
    } else if (key == "o") {
      any_object_ = true;
      objects_.push_back({std::string(rest_of_line(line, tokens_[0])), number});
    } else if (key == "g") {
      groups_.push_back({std::string(rest_of_line(line, tokens_[0])), number});
    } else if (!is_ignored(key)) {
      if (!recognised_) {
        error(tokens_[0].column,
              "'" + std::string(key) + "' is not an OBJ statement: this does not look like an OBJ file",
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
  [[noreturn]] void error(std::size_t column, const std::string& message, const std::string& hint = {}) const {
    fail(ErrorKind::Input, source_, {line_, static_cast<std::uint32_t>(column)}, message, hint);
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
      error(token.column, std::string(what) + " '" + std::string(token.text) + "' is too large");
    }
    if (ec != std::errc() || end != text.data() + text.size()) {
      error(token.column, "expected a number for the " + std::string(what) + ", found '" +
                              std::string(token.text) + "'");
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
      error(tokens_[0].column, "a " + std::string(what) + " needs " + std::to_string(required) +
                                   " numbers, found " + std::to_string(tokens_.size() - 1));
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
    if (ec != std::errc() || end != text.data() + text.size()) {
      error(column, "expected a " + std::string(what) + " index, found '" + std::string(text) + "'");
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
    face_sizes_.push_back(static_cast<std::uint32_t>(n));
    face_object_.push_back(static_cast<std::uint32_t>(objects_.size() - 1));
    face_group_.push_back(static_cast<std::uint32_t>(groups_.size() - 1));
    face_line_.push_back(line_);
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
  std::uint32_t line_ = 0;
  std::vector<Token> tokens_;
  bool recognised_ = false;
  bool any_object_ = false;

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

std::vector<ObjObject> read_obj(std::istream& in, const std::string& source_name) {
  Reader reader(source_name);
  std::string line;
  std::string joined;  // a statement continued over lines with a trailing '\'
  std::uint32_t number = 0;
  std::uint32_t statement_line = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1 && line.starts_with("\xEF\xBB\xBF")) line.erase(0, 3);  // UTF-8 byte order mark
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (joined.empty()) statement_line = number;
    if (!line.empty() && line.back() == '\\') {
      line.back() = ' ';
      joined += line;
      continue;
    }
    if (!joined.empty()) {
      joined += line;
      reader.read_line(joined, statement_line);
      joined.clear();
    } else {
      reader.read_line(line, number);
    }
  }
  if (!joined.empty()) reader.read_line(joined, statement_line);
  if (in.bad()) fail(ErrorKind::Io, source_name, {}, "cannot read: the stream failed", "check the file");
  return reader.finish();
}

std::vector<ObjObject> read_obj_file(const std::filesystem::path& path) {
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
  return read_obj(in, path.string());
}

}  // namespace vern
