// Turned primitives: finding the quarter turns that put a label's canonical
// mesh onto a part's vertices, and writing them as R operations.
#include "inverse/load/orientation.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "forward/primitive_library.hpp"
#include "forward/variants.hpp"
#include "graph/parser.hpp"
#include "graph/writer.hpp"
#include "inverse/infer.hpp"
#include "io/obj_writer.hpp"
#include "support/derive_helpers.hpp"

namespace vern {
namespace {

// The world-space mesh of terminal i of a derivation, as an OBJ would hold it.
Mesh placed(const Derivation& d, std::size_t i, const Mesh& unit) {
  Mesh m = unit;
  for (glm::dvec3& p : m.positions) p = d.terminals[i].scope.to_world(p);
  return m;
}

Derivation derived(const std::string& body) {
  return test::derive_text("a --> " + body + "\n", {3, 2, 1});
}

TEST(Orientation, AnUnturnedPartNeedsNoTurn) {
  const Mesh& wedge = *PrimitiveLibrary::builtin().find("right_angle_triangle");
  const Derivation d = derived("I(right_angle_triangle)");
  const Bounds b = world_bounds(d.terminals[0].scope);
  EXPECT_EQ(find_orientation(wedge, placed(d, 0, wedge).positions, b.min, b.max, 1e-9), Orientation{});
}

TEST(Orientation, FindsTheTurnTheGrammarMade) {
  const Mesh& wedge = *PrimitiveLibrary::builtin().find("right_angle_triangle");
  for (const std::string turn : {"R(z, pi/2)", "R(z, 3*pi/2)", "R(x, pi)", "R(y, pi/2){ R(z, pi/2)"}) {
    const std::string body = turn + "{ I(right_angle_triangle) }" + (turn.find('{') != std::string::npos ? "}" : "");
    const Derivation d = derived(body);
    const Mesh world = placed(d, 0, wedge);
    const Bounds b = world_bounds(d.terminals[0].scope);
    const std::optional<Orientation> found = find_orientation(wedge, world.positions, b.min, b.max, 1e-9);
    ASSERT_TRUE(found.has_value()) << turn;
    // The turns found make the same mesh (a symmetric shape may have
    // another name for the same turn).
    Grammar g;
    const NodeId node = turned_primitive(g, g.label_id("right_angle_triangle"), *found);
    g.rules.push_back({"a", {}, node, {}});
    const std::string text = write_grammar(g);
    const Derivation again = test::derive_text(text, {3, 2, 1});
    const Mesh rebuilt = placed(again, 0, wedge);
    ASSERT_EQ(rebuilt.positions.size(), world.positions.size());
    std::vector<glm::dvec3> x = rebuilt.positions, y = world.positions;
    auto less = [](const glm::dvec3& p, const glm::dvec3& q) {
      return p.x < q.x - 1e-9 || (std::abs(p.x - q.x) <= 1e-9 && (p.y < q.y - 1e-9 || (std::abs(p.y - q.y) <= 1e-9 && p.z < q.z - 1e-9)));
    };
    std::sort(x.begin(), x.end(), less);
    std::sort(y.begin(), y.end(), less);
    for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(glm::length(x[i] - y[i]), 0.0, 1e-9) << turn << " vertex " << i;
  }
}

TEST(Orientation, ASymmetricMeshIsNeverTurned) {
  const Mesh& box = *PrimitiveLibrary::builtin().find("rect");
  const Derivation d = derived("R(z, pi/2){ I(rect) }");
  const Bounds b = world_bounds(d.terminals[0].scope);
  EXPECT_EQ(find_orientation(box, placed(d, 0, box).positions, b.min, b.max, 1e-9), Orientation{});
}

TEST(Orientation, AnotherShapeHasNoTurn) {
  const PrimitiveLibrary& lib = PrimitiveLibrary::builtin();
  const Derivation d = derived("I(pyramid)");
  const Bounds b = world_bounds(d.terminals[0].scope);
  EXPECT_FALSE(find_orientation(*lib.find("right_angle_triangle"), placed(d, 0, *lib.find("pyramid")).positions, b.min, b.max,
                                1e-9));
}

TEST(Orientation, TurnsAreWrittenAsMultiplesOfPi) {
  Grammar g;
  const NodeId node = turned_primitive(g, g.label_id("roof"), {{Axis::Z, 3}, {Axis::X, 2}});
  g.rules.push_back({"a", {}, node, {}});
  EXPECT_NE(write_grammar(g).find("R(z, 3 * pi / 2){ R(x, pi){ I(roof) } }"), std::string::npos) << write_grammar(g);
}

// Do two point sets hold the same points (within tol), ignoring order?
bool same_points(std::vector<glm::dvec3> a, std::vector<glm::dvec3> b, double tol) {
  auto covered = [tol](const std::vector<glm::dvec3>& xs, const std::vector<glm::dvec3>& ys) {
    return std::all_of(xs.begin(), xs.end(), [&](const glm::dvec3& p) {
      return std::any_of(ys.begin(), ys.end(), [&](const glm::dvec3& q) { return glm::length(p - q) <= tol; });
    });
  };
  return covered(a, b) && covered(b, a);
}

// The thesis's better-roofs houses: written as OBJ (meshes turned by the
// grammar's R operations), inferred, and derived again: every part comes
// back with its mesh turned as it was, not only its box.
TEST(OrientationRoundTrip, BetterRoofsComeBackTurnedAsTheyWere) {
  const Grammar source = read_grammar_file(VERN_SOURCE_DIR "/data/grammars/better_roofs.grm");
  const PrimitiveLibrary& lib = PrimitiveLibrary::builtin();
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("vern-orient-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::size_t turned = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    DeriveOptions o;
    o.seed = seed;
    const std::filesystem::path file = dir / ("house" + std::to_string(seed) + ".obj");
    write_obj(single(derive(source, o), 0), lib, file);
    const Example example = load_example(file);
    const Inference inferred = infer({example}, {});
    DeriveOptions again;
    again.size = example_size(example);
    const Derivation d = derive(inferred.grammar, again);
    ASSERT_EQ(d.terminals.size(), example.boxes.size());
    for (const Terminal& t : d.terminals) {
      const std::string& label = d.labels[t.label];
      const Mesh* unit = inferred.primitives.find(label);
      ASSERT_NE(unit, nullptr) << label;
      std::vector<glm::dvec3> mine;
      for (const glm::dvec3& p : unit->positions) mine.push_back(t.scope.to_world(p) + example.min);
      const Bounds b = world_bounds(t.scope);
      bool found = false;
      std::vector<glm::dvec3> theirs;
      for (std::size_t i = 0; i < example.boxes.size(); ++i) {
        const LabelledBox& box = example.boxes[i];
        if (box.label != label || glm::length(box.min - (b.min + example.min)) > 4 * inferred.tolerance ||
            glm::length(box.max - (b.max + example.min)) > 4 * inferred.tolerance)
          continue;
        found = true;
        example.positions.get(i, box.min, box.max, theirs);
        EXPECT_TRUE(same_points(mine, theirs, 4 * inferred.tolerance)) << label << " at seed " << seed;
      }
      EXPECT_TRUE(found) << label;
      if (t.scope.frame != glm::dmat3(1.0)) ++turned;
    }
  }
  EXPECT_GT(turned, 0u);  // the houses do have turned roof pieces
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vern
