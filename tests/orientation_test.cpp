// Turned primitives: finding the quarter turns that put a label's canonical
// mesh onto a part's vertices, and writing them as R operations.
#include "inverse/orientation.hpp"

#include <gtest/gtest.h>

#include "forward/primitive_library.hpp"
#include "graph/writer.hpp"
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
  EXPECT_EQ(find_orientation(wedge, placed(d, 0, wedge), b.min, b.max, 1e-9), Orientation{});
}

TEST(Orientation, FindsTheTurnTheGrammarMade) {
  const Mesh& wedge = *PrimitiveLibrary::builtin().find("right_angle_triangle");
  for (const std::string turn : {"R(z, pi/2)", "R(z, 3*pi/2)", "R(x, pi)", "R(y, pi/2){ R(z, pi/2)"}) {
    const std::string body = turn + "{ I(right_angle_triangle) }" + (turn.find('{') != std::string::npos ? "}" : "");
    const Derivation d = derived(body);
    const Mesh world = placed(d, 0, wedge);
    const Bounds b = world_bounds(d.terminals[0].scope);
    const std::optional<Orientation> found = find_orientation(wedge, world, b.min, b.max, 1e-9);
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
  EXPECT_EQ(find_orientation(box, placed(d, 0, box), b.min, b.max, 1e-9), Orientation{});
}

TEST(Orientation, AnotherShapeHasNoTurn) {
  const PrimitiveLibrary& lib = PrimitiveLibrary::builtin();
  const Derivation d = derived("I(pyramid)");
  const Bounds b = world_bounds(d.terminals[0].scope);
  EXPECT_FALSE(find_orientation(*lib.find("right_angle_triangle"), placed(d, 0, *lib.find("pyramid")), b.min, b.max,
                                1e-9));
}

TEST(Orientation, TurnsAreWrittenAsMultiplesOfPi) {
  Grammar g;
  const NodeId node = turned_primitive(g, g.label_id("roof"), {{Axis::Z, 3}, {Axis::X, 2}});
  g.rules.push_back({"a", {}, node, {}});
  EXPECT_NE(write_grammar(g).find("R(z, 3 * pi / 2){ R(x, pi){ I(roof) } }"), std::string::npos) << write_grammar(g);
}

}  // namespace
}  // namespace vern
