// A style's report: how its examples are seen and drawn.
#include "report/style_report.hpp"

#include <gtest/gtest.h>

#include <regex>

#include "graph/parser.hpp"
#include "io/palette.hpp"
#include "report/png.hpp"

namespace vern {
namespace {

Example example_of(std::vector<LabelledBox> boxes, std::string source = "house.obj") {
  Example e;
  e.source = std::move(source);
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    boxes[i].object = boxes[i].label + "." + std::to_string(i);
    boxes[i].line = i + 1;
  }
  e.boxes = std::move(boxes);
  update_bounds(e);
  return e;
}

LabelledBox part(std::string label, glm::dvec3 min, glm::dvec3 max) {
  LabelledBox b;
  b.label = std::move(label);
  b.min = min;
  b.max = max;
  return b;
}

// The report of these examples alone (no new buildings) under a one-rule grammar.
Report examples_report(const std::vector<Example>& examples) {
  static const Grammar grammar = parse_grammar("building --> I(wall)\n", "test.grm");
  static const PrimitiveLibrary library = PrimitiveLibrary::builtin();
  StyleReportInput in;
  in.title = "test.grm";
  in.grammar = &grammar;
  in.primitives = &library;
  in.examples = &examples;
  in.new_buildings = 0;
  return style_report(in);
}

TEST(StyleReport, FacadesAreSeenStraightInFrontAndBuildingsFromTheirCorner) {
  const std::vector<Example> facades = {example_of({part("window", {0, 0, 0}, {15, 0.2, 20})}),
                                        example_of({part("window", {0, 0, 0}, {15, 0.2, 30})})};
  EXPECT_EQ(elevation_eye(facades), glm::dvec3(0, -1, 0));
  const std::vector<Example> turned = {example_of({part("window", {0, 0, 0}, {0.2, 15, 20})})};
  EXPECT_EQ(elevation_eye(turned), glm::dvec3(-1, 0, 0));
  // One house among facades: all are seen from the corner.
  std::vector<Example> mixed = facades;
  mixed.push_back(example_of({part("wall", {0, 0, 0}, {10, 8, 6})}));
  EXPECT_EQ(elevation_eye(mixed), std::nullopt);
}

TEST(StyleReport, AWindowSetIntoItsWallIsDrawnAsInferenceReadsIt) {
  // The window passes through the wall's whole depth, its face flush with
  // the wall's: drawn as read, the wall (first in the file) hides it.
  const std::vector<Example> examples = {example_of({part("wall", {0, 0, 0}, {4, 0.15, 3}),
                                                    part("window", {1.5, 0, 1}, {2.5, 0.15, 2})})};
  const Report report = examples_report(examples);
  ASSERT_EQ(report.sections.size(), 1u);
  ASSERT_EQ(report.sections[0].galleries.size(), 1u);
  ASSERT_EQ(report.sections[0].galleries[0].pictures.size(), 1u);
  const RgbImage image = read_png(report.sections[0].galleries[0].pictures[0].png);
  // Seen in front (the example is thin), the middle pixel is the window's
  // colour, shaded: its hue, not the wall's.
  const std::size_t at = (static_cast<std::size_t>(image.height) / 2 * image.width + image.width / 2) * 3;
  const glm::dvec3 seen(image.rgb[at], image.rgb[at + 1], image.rgb[at + 2]);
  const Rgb w = label_colour("window"), wall = label_colour("wall");
  const glm::dvec3 window_hue = glm::normalize(glm::dvec3(w.red, w.green, w.blue));
  const glm::dvec3 wall_hue = glm::normalize(glm::dvec3(wall.red, wall.green, wall.blue));
  EXPECT_GT(glm::dot(glm::normalize(seen), window_hue), glm::dot(glm::normalize(seen), wall_hue)) << seen.x << " " << seen.y << " " << seen.z;
}

TEST(StyleReport, TallFacadesGetPicturesTallerThanWide) {
  auto picture_size = [](const std::vector<Example>& examples) {
    const Report report = examples_report(examples);
    const ReportPicture& p = report.sections[0].galleries[0].pictures[0];
    return std::pair(p.width, p.height);
  };
  EXPECT_EQ(picture_size({example_of({part("wall", {0, 0, 0}, {15, 0.2, 30})})}), std::pair(270, 360));
  EXPECT_EQ(picture_size({example_of({part("wall", {0, 0, 0}, {15, 0.2, 10})})}), std::pair(360, 270));
  // Buildings seen from the corner keep the landscape pictures, however tall.
  EXPECT_EQ(picture_size({example_of({part("wall", {0, 0, 0}, {10, 8, 60})})}), std::pair(360, 270));
}

TEST(StyleReport, ExamplesAreCaptionedByTheirFileWithoutItsFolders) {
  EXPECT_EQ(example_caption("examples/a/house.obj"), "house.obj");
  EXPECT_EQ(example_caption("scenes/street.glb (building 2 of 3)"), "street.glb (building 2 of 3)");
  EXPECT_EQ(example_caption("a (b)/c.obj"), "c.obj");
  EXPECT_EQ(example_caption("house.obj"), "house.obj");
}

}  // namespace
}  // namespace vern
