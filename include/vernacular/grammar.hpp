// A grammar: rules that derive buildings (docs/grammar.md is the language).
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

namespace vernacular {

namespace detail {
struct GrammarData;
}

// A value: copies are cheap and independent of each other (the rules are
// shared and never changed; there is nothing to change them with).
class Grammar {
 public:
  // The empty grammar: no rules, derives nothing.
  Grammar();

  // Reads a grammar file. Its @primitives (the parts' meshes) are looked
  // for relative to the file's folder, and only in it or below it.
  // Throws Failure: Io when the file cannot be read, Input when the text is
  // not a grammar (the error's location is the line and column).
  static Grammar read(const std::filesystem::path& file);

  // The same from text; `name` stands for the file in error locations, and
  // @primitives are looked for relative to `folder`.
  static Grammar parse(std::string_view text, std::string name = "<text>", std::filesystem::path folder = ".");

  // The grammar's text as Vernacular writes it (docs/grammar.md): reading
  // it back gives the same grammar.
  std::string text() const;

  // Writes text() to `file` (to a temporary file beside it, synced, then
  // renamed: the old file stays whole until the new one is). Throws
  // Failure (Io).
  void save(const std::filesystem::path& file) const;

  std::string start() const;       // the start rule's label
  std::size_t rule_count() const;  // rules (alternatives of one label count apart)
  // The file read, or empty for a parsed text.
  const std::filesystem::path& file() const;

  // For the implementation (src/api/).
  explicit Grammar(std::shared_ptr<const detail::GrammarData> data);
  const detail::GrammarData& data() const { return *data_; }

 private:
  std::shared_ptr<const detail::GrammarData> data_;
};

}  // namespace vernacular
