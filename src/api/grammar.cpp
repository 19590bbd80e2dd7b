// vernacular::Grammar: the internal grammar behind a shared, unchanging value.
#include "vernacular/grammar.hpp"

#include "api/api_data.hpp"
#include "base/atomic_file.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"

namespace vernacular {

Grammar::Grammar() : data_(std::make_shared<detail::GrammarData>()) {}

Grammar::Grammar(std::shared_ptr<const detail::GrammarData> data) : data_(std::move(data)) {}

Grammar Grammar::read(const std::filesystem::path& file) {
  return detail::guarded([&] {
    auto data = std::make_shared<detail::GrammarData>();
    data->grammar = vern::read_grammar_file(file);
    data->file = file;
    data->folder = file.parent_path();
    return Grammar(std::move(data));
  });
}

Grammar Grammar::parse(std::string_view text, std::string name, std::filesystem::path folder) {
  return detail::guarded([&] {
    auto data = std::make_shared<detail::GrammarData>();
    data->grammar = vern::parse_grammar(text, name);
    data->folder = std::move(folder);
    return Grammar(std::move(data));
  });
}

std::string Grammar::text() const {
  return detail::guarded([&] { return vern::write_grammar(data_->grammar); });
}

void Grammar::save(const std::filesystem::path& file) const {
  detail::guarded([&] { vern::write_file_atomically(file, text()); });
}

std::string Grammar::start() const {
  const vern::Grammar& g = data_->grammar;
  return g.rules.empty() ? std::string() : g.rules[g.start_rule].label;
}

std::size_t Grammar::rule_count() const { return data_->grammar.rules.size(); }

const std::filesystem::path& Grammar::file() const { return data_->file; }

}  // namespace vernacular
