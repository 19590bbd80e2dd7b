// What the public API's values hold, and how internal errors become
// vernacular::Failure. Private to src/api/.
#pragma once

#include <filesystem>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include "base/error.hpp"
#include "forward/primitive_library.hpp"
#include "graph/grammar.hpp"
#include "inverse/load/example.hpp"
#include "vernacular/error.hpp"
#include "vernacular/io.hpp"

namespace vernacular::detail {

struct GrammarData {
  vern::Grammar grammar;
  std::filesystem::path file;    // read from; empty for parsed text
  std::filesystem::path folder;  // where @primitives are looked for
  // An inferred grammar's own meshes (each label's, from its examples);
  // absent: the grammar's @primitives, else the built-in ones.
  std::optional<vern::PrimitiveLibrary> meshes;
};

struct ExampleData {
  vern::Example example;
  std::vector<ExamplePart> parts;
  std::vector<std::string> notes;
};

// The error an internal vern::Error's text describes: its text is
// "[file[:line:column]: ]error: message[\n  hint: hint]".
Error error_of(const vern::Error& e);

// Runs f; what it throws leaves as a Failure (a bug as Internal).
template <class F>
auto guarded(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Failure&) {
    throw;
  } catch (const vern::Error& e) {
    throw Failure(error_of(e), e.what());
  } catch (const std::filesystem::filesystem_error& e) {
    // A file-system call on a user's path that slipped through: the
    // path's fault (a link that leads to itself), not a bug.
    throw Failure(Error{ErrorKind::Io, {e.path1().string()}, std::string("cannot read or write: ") + e.code().message(),
                        "check the path (a link that leads to itself, a folder that cannot be listed)"});
  } catch (const std::bad_alloc&) {
    throw Failure(Error{ErrorKind::Limit, {}, "out of memory", "work on fewer or smaller buildings at once"});
  } catch (const std::exception& e) {
    throw Failure(Error{ErrorKind::Internal, {}, e.what(), "this is a bug in Vernacular: please report it"});
  }
}

}  // namespace vernacular::detail
