// The lines of an OBJ stream, as the reader takes them.
//
// Read in large blocks; a line longer than kMaxObjLine comes out cut at
// kMaxObjLine + 1 bytes (the reader refuses it), so a file without line
// breaks costs one block, not its size. With read-ahead, a second thread
// reads the next lines and parses their plain `v` and `f` lines
// (obj_plain_line.hpp) while the reader takes in the ones before: parsing
// numbers is most of reading a large file. The lines, and so whatever the
// reader makes of them, errors included, are the same either way.
#pragma once

#include <cstdint>
#include <istream>
#include <memory>
#include <string_view>

#include <glm/glm.hpp>

namespace vern {

enum class PlainLine : std::uint8_t { Unread, Vertex, Face };

struct ObjLine {
  std::string_view text;  // without its line break; valid until the next line
  bool last = false;      // ends the stream without a line break
  // With read-ahead: the line, less a trailing '\r', is a plain vertex or
  // face, parsed; otherwise Unread.
  PlainLine plain = PlainLine::Unread;
  glm::dvec3 vertex{0.0};
  const std::uint32_t* indices = nullptr;  // a face's, as written (from 1)
  std::size_t index_count = 0;
};

class ObjLines {
 public:
  ObjLines(std::istream& in, bool read_ahead);
  ~ObjLines();  // stops the read-ahead, if any, wherever it is
  ObjLines(const ObjLines&) = delete;
  ObjLines& operator=(const ObjLines&) = delete;

  // The next line; false at the end of the stream.
  bool next(ObjLine& line);
  // Whether reading the stream failed (after next returned false).
  bool failed() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace vern
