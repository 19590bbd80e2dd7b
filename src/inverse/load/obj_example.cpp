#include "inverse/load/obj_example.hpp"

#include <optional>

#include "base/error.hpp"
#include "graph/label.hpp"
#include "inverse/load/part_adder.hpp"
#include "io/obj_reader.hpp"

namespace vern {

namespace fs = std::filesystem;

Example load_obj_example(const fs::path& path, const ExampleLimits& limits, bool read_ahead) {
  Example ex;
  ex.source = path.string();
  PartAdder adder(ex, limits);
  // Objects arrive while the file is read: an unnamed one is reported once
  // the whole file has been read, so that errors further on come first.
  std::optional<std::uint32_t> unnamed;
  constexpr std::uint32_t kUngrouped = 1u << 31;
  std::uint32_t ungrouped = 0;
  const ObjLimits obj_limits{limits.max_parts, too_many_parts_hint(limits), limits.max_faces, too_many_faces_hint(limits),
                             limits.obj_up};
  read_obj_file(path, obj_limits, [&](const ObjObject& o) {
    if (o.name.empty()) {
      if (!unnamed) unnamed = o.line;
    } else if (!unnamed) {
      // An object before any `g` is a group of its own (Blender writes no
      // groups by default): numbered past any count of `g` statements.
      const std::uint32_t group = o.group != 0 ? o.group : kUngrouped + ungrouped++;
      adder.add(read_label(o.name, NameOf::Part, ex.source, {o.line, 1}, "the object name"), o.line, o.mesh,
                shown_name(o.name), group);
    }
  }, read_ahead);
  if (unnamed) {
    fail(ErrorKind::Input, ex.source, {*unnamed, 1},
         "these faces have no name: inference cannot tell which primitive they are",
         "start each part with `o <label>` naming its primitive (e.g. `o window.001`)");
  }
  if (ex.boxes.empty()) {
    fail(ErrorKind::Input, ex.source, {},
         "has no labelled objects; each part must be an OBJ object `o name` with its faces",
         "write `o <label>` before each part's vertices and faces (e.g. `o window.001`), one object per primitive");
  }
  return ex;
}

}  // namespace vern
