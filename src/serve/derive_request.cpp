#include "serve/derive_request.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <optional>

#include "base/error.hpp"
#include "forward/program.hpp"
#include "graph/label.hpp"
#include "graph/parser.hpp"
#include "io/palette.hpp"
#include "serve/api_json.hpp"

namespace vern {

namespace {

using nlohmann::json;

json mesh_json(const Mesh& mesh) {
  json positions = json::array(), indices = json::array();
  for (const glm::dvec3& p : mesh.positions) positions.insert(positions.end(), {p.x, p.y, p.z});
  std::size_t first = 0;
  for (const std::uint32_t n : mesh.face_sizes) {
    for (std::uint32_t k = 1; k + 1 < n; ++k)
      indices.insert(indices.end(), {mesh.corners[first].position, mesh.corners[first + k].position,
                                     mesh.corners[first + k + 1].position});
    first += n;
  }
  return {{"positions", std::move(positions)}, {"indices", std::move(indices)}};
}

json building_json(const Derivation& d, std::uint64_t seed) {
  json parts = json::array();
  for (std::size_t i = 0; i < d.terminals.size(); ++i) {
    const Terminal& t = d.terminals[i];
    const Scope& s = t.scope;
    json matrix = json::array();
    for (int c = 0; c < 3; ++c) {
      const glm::dvec3 axis = s.frame[c] * s.size[c];
      matrix.insert(matrix.end(), {axis.x, axis.y, axis.z, 0.0});
    }
    matrix.insert(matrix.end(), {s.origin.x, s.origin.y, s.origin.z, 1.0});
    json part = {{"label", t.label}, {"matrix", std::move(matrix)}};
    if (t.coloured) part["colour"] = {t.colour.red, t.colour.green, t.colour.blue};
    if (i < d.traces.size()) {
      const TerminalTrace& trace = d.traces[i];
      part["at"] = {trace.at.line, trace.at.column};
      part["rules"] = trace.rules;
      part["chain"] = trace.chain;
      json path = json::array();
      for (const TerminalTrace::Step& step : trace.path)
        path.push_back({step.op, step.index, static_cast<int>(step.axis)});
      part["path"] = std::move(path);
    }
    parts.push_back(std::move(part));
  }
  return {{"seed", seed}, {"size", {d.start.size.x, d.start.size.y, d.start.size.z}}, {"parts", std::move(parts)}};
}

}  // namespace

ApiAnswer derive_request(std::string_view request, const ServeSession& session) {
  const json in = json::parse(request, nullptr, false);
  if (in.is_discarded() || !in.is_object()) return bad_request("the request is not a JSON object");
  if (!in.contains("text") || !in["text"].is_string()) return bad_request("the request has no \"text\" string");
  const std::string text = in["text"].get<std::string>();
  std::uint64_t seed = 1;
  int count = 1;
  if (in.contains("seed")) {
    if (!in["seed"].is_number_unsigned()) return bad_request("\"seed\" must be a whole number >= 0");
    seed = in["seed"].get<std::uint64_t>();
  }
  if (in.contains("count")) {
    if (!in["count"].is_number_integer() || in["count"].get<long long>() < 1 || in["count"].get<long long>() > kMostBuildings)
      return bad_request("\"count\" must be a whole number from 1 to " + std::to_string(kMostBuildings));
    count = in["count"].get<int>();
  }
  std::optional<glm::dvec3> plot;
  if (in.contains("size")) {
    const json& size = in["size"];
    if (!size.is_array() || size.size() != 3 ||
        !std::all_of(size.begin(), size.end(), [](const json& v) { return v.is_number() && v.get<double>() > 0 && v.get<double>() <= 1e6; }))
      return bad_request("\"size\" must be the plot's three sizes in metres, each > 0 and at most 1,000,000");
    plot = glm::dvec3(size[0].get<double>(), size[1].get<double>(), size[2].get<double>());
  }
  try {
    const Grammar grammar = parse_grammar(text, kEditorSource);
    const Program program = compile(grammar);
    json buildings = json::array();
    std::vector<std::string> labels;
    std::uint64_t parts = 0;
    std::string note;
    for (int i = 0; i < count; ++i) {
      DeriveOptions options;
      options.seed = seed + static_cast<std::uint64_t>(i);
      options.limits = session.limits;
      options.trace = true;
      options.size = plot;
      const Derivation d = derive(program, options);
      labels = d.labels;
      buildings.push_back(building_json(d, options.seed));
      parts += d.terminals.size();
      // Each building within the limits, but a page of them past what a
      // browser draws at once: the rest are left out, and the page says so.
      if (parts >= session.most_parts && i + 1 < count) {
        note = "the first " + std::to_string(i + 1) + " of " + std::to_string(count) + " buildings: they have " +
               std::to_string(parts) + " parts, and a page shows up to " + std::to_string(session.most_parts);
        break;
      }
    }
    json colours = json::object(), meshes = json::object();
    for (const std::string& label : labels) {
      const Rgb c = label_colour(label_as_word(label));
      colours[label] = {c.red, c.green, c.blue};
      const Mesh* mesh = session.primitives.find(label);
      meshes[label] = mesh_json(mesh ? *mesh : session.primitives.box());
    }
    json rules = json::array();
    for (const Rule& r : grammar.rules) rules.push_back({{"label", r.label}, {"line", r.loc.line}});
    return {200, dumped(json{{"ok", true},
                      {"labels", labels},
                      {"colours", std::move(colours)},
                      {"meshes", std::move(meshes)},
                      {"rules", std::move(rules)},
                      {"buildings", std::move(buildings)},
                      {"note", note}})};
  } catch (const Error& e) {
    // The grammar's own fault, as the editor shows it: still an answer.
    return {200, dumped(json{{"ok", false}, {"error", error_json(e)}})};
  }
}

std::string session_json(const ServeSession& session) {
  json examples = json::array();
  for (const Example& e : session.examples) {
    json parts = json::array();
    for (const LabelledBox& b : e.boxes)
      parts.push_back({{"label", b.label}, {"min", {b.min.x, b.min.y, b.min.z}}, {"max", {b.max.x, b.max.y, b.max.z}}});
    examples.push_back({{"name", e.source}, {"parts", std::move(parts)}});
  }
  json colours = json::object();
  for (const Example& e : session.examples)
    for (const LabelledBox& b : e.boxes) {
      const Rgb c = label_colour(label_as_word(b.label));
      colours[b.label] = {c.red, c.green, c.blue};
    }
  return dumped(json{{"name", session.grammar_name}, {"text", session.grammar_text}, {"examples", std::move(examples)},
                     {"colours", std::move(colours)}});
}

}  // namespace vern
