// infer and check as a user meets them: the bundled examples end to end,
// and bad input refused with a clear message and nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <numbers>
#include <random>
#include <regex>
#include <sstream>

#include <glm/glm.hpp>

#include "graph/description_length.hpp"
#include "graph/parser.hpp"
#include "io/gltf_container.hpp"
#include "report/png.hpp"
#include "support/example_helpers.hpp"
#include "support/run_command.hpp"

namespace vern {
namespace {

namespace fs = std::filesystem;
using test::list_folder;
using test::read_file;
using test::run_program;
using test::TempFolder;
using test::write_text;

const std::string kExamples = VERN_SOURCE_DIR "/data/examples/";
const std::string kGrammars = VERN_SOURCE_DIR "/data/grammars/";

TEST(InferCli, GarageExamplesToGrammarToCheckToNewBuildings) {
  TempFolder dir;
  auto r = run_program("infer", {kExamples + "garage", "-o", "garage.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("infer: 10 examples -> garage.grm"), std::string::npos) << r.err;
  // The summary says how much the grammar says: the same description
  // length as evaluate's (graph/description_length.hpp), read back here.
  const std::size_t at = r.err.find("description length ");
  ASSERT_NE(at, std::string::npos) << r.err;
  std::size_t total = 0, operations = 0, numbers = 0;
  ASSERT_EQ(std::sscanf(r.err.c_str() + at, "description length %zu (%zu operations, %zu numbers)", &total,
                        &operations, &numbers),
            3)
      << r.err;
  EXPECT_EQ(total, operations + numbers);
  const DescriptionLength dl = description_length(read_grammar_file((dir / "garage.grm").string()));
  EXPECT_EQ(operations, dl.operations) << r.err;
  EXPECT_EQ(numbers, dl.numbers) << r.err;
  EXPECT_EQ(list_folder(dir.path()), (std::vector<std::string>{"garage.grm", "garage.prims.mtl", "garage.prims.obj"}));
  const std::string grammar = read_file(dir / "garage.grm");
  EXPECT_NE(grammar.find("@primitives \"garage.prims.obj\""), std::string::npos);
  EXPECT_NE(grammar.find("@scope 10, 10, 10"), std::string::npos) << grammar;

  r = run_program("check", {"garage.grm", kExamples + "garage"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("10 of 10 examples derivable"), std::string::npos) << r.out;

  r = run_program("generate", {"garage.grm", "-n", "5", "-o", "new/"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;  // the meshes came with the grammar
  EXPECT_NE(read_file(dir / "new/variant_004.obj").find("o triangle"), std::string::npos);
}

// A folder of examples (a bundled set's) copied into dir/examples as
// modelled away from the origin and exported as a modelling tool does:
// example i (in name order) moved by offset(i), every coordinate through a
// 32-bit float and written with six decimals.
void far_examples(const fs::path& dir, const std::string& folder, const std::function<glm::dvec3(int)>& offset) {
  fs::create_directory(dir / "examples");
  int i = 0;
  for (const std::string& name : list_folder(folder)) {
    if (name.size() < 4 || name.substr(name.size() - 4) != ".obj") continue;
    const glm::dvec3 d = offset(i++);
    std::istringstream in(read_file(folder + "/" + name));
    std::string text, line;
    while (std::getline(in, line)) {
      double x = 0, y = 0, z = 0;
      if (line.rfind("v ", 0) == 0 && std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z) == 3) {
        char buffer[96];
        std::snprintf(buffer, sizeof buffer, "v %.6f %.6f %.6f", static_cast<double>(static_cast<float>(x + d.x)),
                      static_cast<double>(static_cast<float>(y + d.y)), static_cast<double>(static_cast<float>(z + d.z)));
        line = buffer;
      }
      text += line + "\n";
    }
    write_text(dir / ("examples/" + name), text);
  }
}

// The bundled garages modelled 2 km from the origin (noisy to 0.1 mm
// there). The tolerance follows the coordinates, so infer still finds the
// house's two thirds (~2 : ~1, not ~6.666687 : ~3.333313) and check,
// taking each file's tolerance the same way, derives every garage.
// RFC 4648 base64 back to bytes (what the pages hold their pictures in).
std::string base64_decoded(const std::string& text) {
  static const std::string kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  std::uint32_t bits = 0;
  int held = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<std::uint32_t>(kDigits.find(c));
    held += 6;
    if (held >= 8) {
      held -= 8;
      out += static_cast<char>((bits >> held) & 0xff);
    }
  }
  return out;
}

// infer --report: one page, with the examples' pictures beside new
// buildings', and the grammar as written.
TEST(InferCli, AReportShowsTheExamplesBesideNewBuildingsAndTheGrammarAsWritten) {
  TempFolder dir;
  auto r = run_program("infer", {kExamples + "garage", "-o", "garage.grm", "--report", "garage.html"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("infer: report -> garage.html"), std::string::npos) << r.err;
  EXPECT_EQ(list_folder(dir.path()),
            (std::vector<std::string>{"garage.grm", "garage.html", "garage.prims.mtl", "garage.prims.obj"}));
  const std::string html = read_file(dir / "garage.html");
  // Ten examples, eight new buildings, each a picture inside the page.
  const std::regex picture("<img alt=\"([^\"]*)\"[^>]*src=\"data:image/png;base64,([A-Za-z0-9+/=]*)\"");
  std::vector<std::string> captions;
  std::vector<RgbImage> images;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), picture); it != std::sregex_iterator(); ++it) {
    captions.push_back((*it)[1]);
    images.push_back(read_png(base64_decoded((*it)[2])));
  }
  ASSERT_EQ(captions.size(), 18u) << html.substr(0, 2000);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(captions[i], "variant_00" + std::to_string(i) + ".obj");
  for (int i = 0; i < 8; ++i) EXPECT_EQ(captions[10 + i], "seed " + std::to_string(1 + i));
  for (const RgbImage& image : images) {
    ASSERT_EQ(image.width, 360);
    ASSERT_EQ(image.height, 270);
    // A building is drawn: many pixels are not the white of the sky.
    std::size_t drawn = 0;
    for (std::size_t p = 0; p < image.rgb.size(); p += 3)
      drawn += image.rgb[p] != 255 || image.rgb[p + 1] != 255 || image.rgb[p + 2] != 255;
    EXPECT_GT(drawn, 5000u);
  }
  // The garage's examples differ: so do their pictures.
  EXPECT_NE(images[0], images[1]);
  // Every line of the grammar file is on the page, numbered.
  std::istringstream grammar(read_file(dir / "garage.grm"));
  std::string line;
  for (int n = 1; std::getline(grammar, line); ++n) {
    std::string escaped;
    for (char c : line)
      escaped += c == '"'    ? std::string("&quot;")
                 : c == '\'' ? std::string("&#39;")
                 : c == '&'  ? std::string("&amp;")
                 : c == '<'  ? std::string("&lt;")
                 : c == '>'  ? std::string("&gt;")
                             : std::string(1, c);
    EXPECT_NE(html.find("<span class=\"ln\">" + std::to_string(n) + "</span>" + escaped + "\n"), std::string::npos) << line;
  }
  // Same examples and seed, same page, byte for byte, on one thread or two.
  for (const char* threads : {"1", "2"}) {
    r = run_program("infer", {kExamples + "garage", "-o", "again.grm", "--report", "again.html", "-j", threads}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::string again = read_file(dir / "again.html");
    // The page names its grammar and meshes files; otherwise the same.
    for (std::size_t at; (at = again.find("again.")) != std::string::npos;) again.replace(at, 6, "garage.");
    EXPECT_TRUE(again == html) << "threads " << threads;
  }
}

TEST(InferCli, AReportIsAnHtmlFileApartFromTheOtherOutputs) {
  TempFolder dir;
  auto r = run_program("infer", {kExamples + "garage", "-o", "garage.grm", "--report", "garage.png"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("--report must name an .html file"), std::string::npos) << r.err;
  r = run_program("infer", {kExamples + "garage", "-o", "garage.html", "--report", "garage.html"}, dir.path());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(list_folder(dir.path()).empty());
}

TEST(InferCli, ExamplesFarFromTheOriginKeepTheirRatiosAndCheck) {
  TempFolder dir;
  far_examples(dir.path(), kExamples + "garage", [](int) { return glm::dvec3(2000, 1500, 0); });
  auto r = run_program("infer", {"examples", "-o", "far.grm", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string grammar = read_file(dir / "far.grm");
  EXPECT_NE(grammar.find("~2 : rectTriangleZ"), std::string::npos) << grammar;
  r = run_program("check", {"far.grm", "examples", "--brief"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("10 of 10 examples derivable"), std::string::npos) << r.out;
}

// Issue 16, item 3: houses each modelled at its own distance from the
// origin, the first at it, the last 63 km away (noisy to 4 mm there). infer
// merged sizes within the farthest house's tolerance (5 cm), holding the
// house at the origin to less than check, which takes each house's own:
// 5 of 10 were derivable. A grammar infer writes passes check on the same
// examples with default options.
TEST(InferCli, ExamplesEachAtItsOwnDistanceFromTheOriginAllCheck) {
  TempFolder dir;
  far_examples(dir.path(), kExamples + "modern_houses", [](int i) { return glm::dvec3(7000.0 * i, -3000.0 * i, 0); });
  auto r = run_program("infer", {"examples", "-o", "far.grm", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_program("check", {"far.grm", "examples", "--brief"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("10 of 10 examples derivable"), std::string::npos) << r.out;
}

// Towers 200 m high, all 11 km from the origin (noisy to a millimetre,
// tolerance 1 cm): a row of windows seen 28 to 31 times on lengths of 27
// to 30 m was written repeat(x, 0.97), which on 30.13 m makes 32 tiles,
// not the 31 seen. Its tile counts had been left behind when the splits
// below it were redrawn, so no tile was fitted to them.
TEST(InferCli, RowsOfTowersFarFromTheOriginKeepTheirTileCounts) {
  TempFolder dir;
  auto r = run_program("generate", {kGrammars + "modern_houses.grm", "-n", "3", "-s", "7", "--scope", "200", "150",
                                    "200", "-o", "towers/", "-q"},
                       dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  far_examples(dir.path(), (dir / "towers").string(), [](int) { return glm::dvec3(10000, 0, 5000); });
  r = run_program("infer", {"examples", "-o", "far.grm", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_program("check", {"far.grm", "examples", "--brief"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("3 of 3 examples derivable"), std::string::npos) << r.out;
}

TEST(InferCli, EveryBundledExampleSetIsDerivableFromWhatIsInferredFromIt) {
  for (const std::string set : {"better_roofs", "modern_houses", "skyscraper_city"}) {
    SCOPED_TRACE(set);
    TempFolder dir;
    auto r = run_program("infer", {kExamples + set, "-o", "style.grm", "-q"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    r = run_program("check", {"style.grm", kExamples + set, "--brief"}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.out;
    EXPECT_NE(r.out.find("10 of 10 examples derivable"), std::string::npos) << r.out;
  }
}

TEST(InferCli, TheCityComesBackAsAShortGrammar) {
  // Ten cities of some 2,000 towers each: rows of unlike buildings become
  // repeats of a choice and rows of one kind share it, so the grammar is
  // about as long as the thesis's hand-written one (issue 4: at most 150
  // lines; the thesis's own inference wrote 2,268).
  TempFolder dir;
  auto r = run_program("infer", {kExamples + "skyscraper_city", "-o", "city.grm", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read_file(dir / "city.grm");
  EXPECT_LE(std::count(text.begin(), text.end(), '\n'), 150) << text;
  r = run_program("check", {"city.grm", kExamples + "skyscraper_city", "--brief"}, dir.path());
  EXPECT_NE(r.out.find("10 of 10 examples derivable"), std::string::npos) << r.out;
}

TEST(InferCli, CheckSaysWhenABuildingDoesNotFitAndWhere) {
  TempFolder dir;
  ASSERT_EQ(run_program("infer", {kExamples + "garage", "-o", "garage.grm", "-q"}, dir.path()).exit_code, 0);
  const auto r = run_program("check", {"garage.grm", kExamples + "better_roofs/variant_000.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("variant_000.obj: NOT derivable: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0 of 1 example derivable"), std::string::npos) << r.out;
}

TEST(InferCli, CheckOnTheHandWrittenGrammarsPlot) {
  // The city's towers stop below its 200 x 200 x 80 plot: on the examples'
  // own extent the grammar cannot fit them, on its plot it does.
  const std::string city = kExamples + "skyscraper_city/variant_000.glb";
  const std::string grammar = VERN_SOURCE_DIR "/data/grammars/skyscraper_city.grm";
  auto r = run_program("check", {grammar, city, "--brief", "--scope", "200", "200", "80"});
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("1 of 1 example derivable"), std::string::npos) << r.out;
}

// A box as Blender's OBJ exporter writes it by default: y up, -z forward,
// so the grammar's (x, y, z) is the file's (x, z, -y); six decimals.
std::string blender_box(const std::string& name, glm::dvec3 lo, glm::dvec3 hi, int& base) {
  std::string text = "o " + name + "\n";
  char line[96];
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", p.x, p.z, -p.y);
    text += line;
  }
  for (const char* f : {"1 3 4 2", "5 6 8 7", "1 2 6 5", "3 7 8 4", "1 5 7 3", "2 4 8 6"}) {
    std::istringstream corners(f);
    text += "f";
    for (int c; corners >> c;) text += " " + std::to_string(base + c - 1);
    text += "\n";
  }
  base += 8;
  return text;
}

// Houses modelled z-up in Blender and exported with its defaults come
// back with their height on z; --up z reads a file as written; generate's
// default OBJ is what infer reads by default.
TEST(InferCli, BlenderExportedObjHasItsHeightOnZ) {
  TempFolder dir;
  for (const double width : {6.0, 8.0}) {
    int base = 1;
    std::string text = "# Blender 3.4.1\n# www.blender.org\nmtllib house.mtl\n";
    text += blender_box("wall", {0, 0, 0}, {width, 4, 2.7}, base);
    text += blender_box("roof", {0, 0, 2.7}, {width, 4, 3.9}, base);
    write_text(dir / ("house_" + std::to_string(static_cast<int>(width)) + ".obj"), text);
  }
  auto r = run_program("infer", {"house_6.obj", "house_8.obj", "-o", "house.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::string grammar = read_file(dir / "house.grm");
  // Widths 6 and 8, 4 deep, 3.9 high; walls 2.7 and roofs 1.2 high: 9 to 4.
  EXPECT_NE(grammar.find(", 4, 3.9\n@primitives"), std::string::npos) << grammar;
  EXPECT_NE(grammar.find("building --> split(z){ ~9 : I(wall) | ~4 : I(roof) }"), std::string::npos) << grammar;
  r = run_program("check", {"house.grm", "house_6.obj", "house_8.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  // The primitives infer writes declare their up axis, and read back so.
  EXPECT_NE(read_file(dir / "house.prims.obj").find("\n# up y\n"), std::string::npos);
  r = run_program("generate", {"house.grm", "-o", "again.obj", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_program("check", {"house.grm", "again.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;

  r = run_program("infer", {"house_6.obj", "--up", "z", "-o", "lying.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  grammar = read_file(dir / "lying.grm");
  EXPECT_NE(grammar.find("@scope 6, 3.9, 4\n"), std::string::npos) << grammar;  // lying on its back
  r = run_program("check", {"house.grm", "house_6.obj", "--up", "x"}, dir.path());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--up"), std::string::npos) << r.err;
}

// Boxes as Blender's glTF exporter writes them: a unit cube mesh placed by
// each object's translation and scale, numbers Blender keeps as 32-bit
// floats and writes as the doubles they are (12.600000381469727 for 12.6);
// y up, so the grammar's (x, y, z) is the file's (x, z, -y).
std::string blender_gltf(const std::vector<std::pair<std::string, std::pair<glm::dvec3, glm::dvec3>>>& boxes) {
  std::string bytes;
  auto put = [&](const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); };
  for (int i = 0; i < 8; ++i) {
    const float v[3] = {static_cast<float>(i & 1), static_cast<float>((i >> 1) & 1), static_cast<float>((i >> 2) & 1)};
    put(v, sizeof v);
  }
  for (const int corner : {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                           2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5}) {
    const auto t = static_cast<std::uint16_t>(corner);
    put(&t, sizeof t);
  }
  auto f32 = [](double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", static_cast<double>(static_cast<float>(v)));
    return std::string(text);
  };
  std::string nodes, roots;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const auto& [lo, hi] = boxes[i].second;
    nodes += std::string(i ? ",\n" : "") + R"({"name": ")" + boxes[i].first + R"(", "mesh": 0, "translation": [)" +
             f32(lo.x) + ", " + f32(lo.z) + ", " + f32(-hi.y) + R"(], "scale": [)" + f32(hi.x - lo.x) + ", " +
             f32(hi.z - lo.z) + ", " + f32(hi.y - lo.y) + "]}";
    roots += (i ? ", " : "") + std::to_string(i);
  }
  return R"({"asset": {"version": "2.0", "generator": "Khronos glTF Blender I/O v3.4.50"},
  "buffers": [{"byteLength": 168, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}],
  "bufferViews": [{"buffer": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "nodes": [)" + nodes + R"(], "scenes": [{"nodes": [)" + roots + R"(]}], "scene": 0})";
}

// A grammar's text without its comments and its @primitives line, which
// name the files.
std::string grammar_body(const fs::path& file) {
  std::string text;
  std::istringstream in(read_file(file));
  for (std::string line; std::getline(in, line);)
    if (!line.starts_with("#") && !line.starts_with("@primitives")) text += line + "\n";
  return text;
}

// One Blender scene of houses exported as OBJ (six decimals) and as glTF
// (32-bit floats written as doubles) gives one grammar: the floats' noise
// (15.600000381469727, and sizes computed from it) comes out as the
// numbers typed, ranges' bounds included (rand(..., 18.600001) before).
TEST(InferCli, AnObjAndAGltfOfOneBlenderSceneGiveOneGrammar) {
  TempFolder dir;
  fs::create_directories(dir / "obj");
  fs::create_directories(dir / "gltf");
  // Widths and heights whose floats lie outside the decimals at the
  // extremes (4.1 and 4.4 below, 15.6 and 13.3 above), where a range's
  // bounds are drawn from.
  const double sizes[4][2] = {{4.1, 4.4}, {9.7, 7.8}, {15.6, 13.3}, {6.1, 5.3}};
  std::vector<std::string> objs, gltfs;
  for (int i = 0; i < 4; ++i) {
    const double w = sizes[i][0], h = sizes[i][1];
    const glm::dvec3 wall_hi(w, 2.3, h * 0.8), roof_lo(0, 0, h * 0.8), roof_hi(w, 2.3, h);
    int base = 1;
    const std::string name = "house_" + std::to_string(i);
    std::string obj = "# Blender 3.4.1\n" + blender_box("wall", {0, 0, 0}, wall_hi, base);
    obj += blender_box("roof", roof_lo, roof_hi, base);
    write_text(dir / "obj" / (name + ".obj"), obj);
    write_text(dir / "gltf" / (name + ".gltf"), blender_gltf({{"wall", {{0, 0, 0}, wall_hi}}, {"roof", {roof_lo, roof_hi}}}));
    objs.push_back("obj/" + name + ".obj");
    gltfs.push_back("gltf/" + name + ".gltf");
  }
  auto grammar_of = [&](std::vector<std::string> files, const std::string& out) {
    files.insert(files.end(), {"-o", out, "-q"});
    const auto r = run_program("infer", files, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return grammar_body(dir / out);
  };
  const std::string from_obj = grammar_of(objs, "obj.grm");
  const std::string from_gltf = grammar_of(gltfs, "gltf.grm");
  EXPECT_EQ(from_obj, from_gltf);
  // Numbers as typed: none has the float's digits (15.600001, 4.099999).
  EXPECT_FALSE(std::regex_search(from_gltf, std::regex("[0-9]\\.[0-9]{5}"))) << from_gltf;
  for (const auto& [grammar, files] : {std::pair{"obj.grm", objs}, std::pair{"gltf.grm", gltfs}}) {
    std::vector<std::string> args = {grammar};
    args.insert(args.end(), files.begin(), files.end());
    const auto r = run_program("check", args, dir.path());
    EXPECT_EQ(r.exit_code, 0) << grammar << "\n" << r.out << r.err;
  }
}

// A Blender scene of three houses, each a wall with windows set into it
// and a roof, standing apart, exported with default settings (an object
// each, no groups; glTF: a root node each): each house is an example, as
// it would be in a file of its own, and the OBJ and the glTF give one
// grammar. Read whole (--buildings file), the scene is one example.
TEST(InferCli, ABlenderSceneOfHousesIsAnExampleForEachHouse) {
  TempFolder dir;
  fs::create_directories(dir / "one");
  std::vector<std::pair<std::string, std::pair<glm::dvec3, glm::dvec3>>> scene;
  std::vector<std::string> own;
  double x = 0;
  for (const int bays : {2, 3, 4}) {
    const double width = 2.4 * bays;
    std::vector<std::pair<std::string, std::pair<glm::dvec3, glm::dvec3>>> house = {
        {"wall", {{x, 0, 0}, {x + width, 5, 3}}}, {"roof", {{x, 0, 3}, {x + width, 5, 4.5}}}};
    for (int i = 0; i < bays; ++i)
      house.push_back({"window", {{x + 2.4 * i + 0.7, 0, 1}, {x + 2.4 * i + 1.7, 0.2, 2.2}}});
    own.push_back("one/house" + std::to_string(bays) + ".gltf");
    write_text(dir / own.back(), blender_gltf(house));
    scene.insert(scene.end(), house.begin(), house.end());
    x += width + 3;
  }
  write_text(dir / "scene.gltf", blender_gltf(scene));
  int base = 1;
  std::string obj = "# Blender 3.4.1\n# www.blender.org\nmtllib scene.mtl\n";
  for (const auto& [name, box] : scene) obj += blender_box(name, box.first, box.second, base);
  write_text(dir / "scene.obj", obj);

  auto r = run_program("infer", {"one", "-o", "one.grm", "-q"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const std::string file : {"scene.obj", "scene.gltf"}) {
    r = run_program("infer", {file, "-o", file + ".grm"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("note: " + file + " holds 3 buildings standing apart"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("infer: 3 examples -> "), std::string::npos) << r.err;
    EXPECT_EQ(grammar_body(dir / (file + ".grm")), grammar_body(dir / "one.grm")) << file;
    r = run_program("check", {"one.grm", file}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find(file + " (building 2 of 3): derivable"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("3 of 3 examples derivable"), std::string::npos) << r.out;
    r = run_program("check", {"one.grm", file, "--buildings", "file"}, dir.path());
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_NE(r.out.find("0 of 1 example derivable"), std::string::npos) << r.out;
  }
  r = run_program("infer", {"scene.obj", "--buildings", "file", "-o", "whole.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("infer: 1 example -> "), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("note:"), std::string::npos) << r.err;
}

// generate's files of several buildings (a glTF node and an OBJ group per
// building) read back as those buildings: the same grammar as from a file
// per building; a city, one building of the grammar, stays one example.
TEST(InferCli, AFileOfSeveralBuildingsGenerateWroteIsAnExampleForEach) {
  TempFolder dir;
  ASSERT_EQ(run_program("generate", {kGrammars + "garage.grm", "-n", "4", "-o", "one/", "-q"}, dir.path()).exit_code, 0);
  ASSERT_EQ(run_program("infer", {"one", "-o", "one.grm", "-q"}, dir.path()).exit_code, 0);
  for (const std::string file : {"street.glb", "street.obj"}) {
    ASSERT_EQ(run_program("generate", {kGrammars + "garage.grm", "-n", "4", "-o", file, "-q"}, dir.path()).exit_code, 0);
    auto r = run_program("infer", {file, "-o", file + ".grm"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("infer: 4 examples -> "), std::string::npos) << r.err;
    EXPECT_EQ(grammar_body(dir / (file + ".grm")), grammar_body(dir / "one.grm")) << file;
    r = run_program("check", {kGrammars + "garage.grm", file}, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_NE(r.out.find("4 of 4 examples derivable"), std::string::npos) << r.out;
  }
  auto r = run_program("infer", {kExamples + "skyscraper_city/variant_000.glb", "-o", "city.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("infer: 1 example -> "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("variant_000.glb looks like 72 buildings standing apart"), std::string::npos) << r.err;
}

// The OBJ objects a file names, sorted: its labels as written.
std::vector<std::string> object_lines(const std::string& obj) {
  std::vector<std::string> names;
  std::istringstream in(obj);
  for (std::string line; std::getline(in, line);)
    if (line.starts_with("o ")) names.push_back(line);
  std::sort(names.begin(), names.end());
  return names;
}

// A grammar's labels go round: written into OBJ, glTF and instanced glTF
// buildings, inferred back, generated again, they are the same labels,
// however unusual (graph/label.hpp): '#' and a final '\' that OBJ reads
// otherwise, a ".2" that reads as a copy number, spaces, '%', UTF-8, and
// one that looks like an instanced node's colour.
TEST(InferCli, UnusualLabelsGoRoundExamplesGrammarAndBuildings) {
  TempFolder dir;
  const std::vector<std::string> labels = {"#x",    "a b",          "a_b", "a#b", "v1.2", "50%", "back\\",
                                           "fen\xC3\xAAtre", "a colour_ff0000", "window"};
  std::string grammar = "plot --> split(x){ 1 : colour(red)";
  for (const std::string& label : labels) {
    std::string quoted;
    for (const char c : label) quoted += c == '\\' || c == '"' ? std::string("\\") + c : std::string(1, c);
    grammar += " | 1 : I(\"" + quoted + "\")";
  }
  write_text(dir / "source.grm", grammar + " }\n");
  std::vector<std::string> expected = labels;
  expected.push_back("rect");  // colour(red)'s
  std::sort(expected.begin(), expected.end());

  auto r = run_program("generate", {"source.grm", "--scope", "11", "1", "1", "-q", "-o", "source.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> written = object_lines(read_file(dir / "source.obj"));
  ASSERT_EQ(written.size(), expected.size());
  for (const std::string out : {"b.obj", "b.glb", "instanced.glb"}) {
    SCOPED_TRACE(out);
    std::vector<std::string> args = {"source.grm", "--scope", "11", "1", "1", "-q", "-o", out};
    if (out == "instanced.glb") args.push_back("--instancing");
    r = run_program("generate", args, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string stem = fs::path(out).stem().string() + fs::path(out).extension().string().substr(1);
    r = run_program("infer", {out, "-o", stem + ".grm", "-q"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Grammar inferred = read_grammar_file((dir / (stem + ".grm")).string());
    std::vector<std::string> got = inferred.labels();
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, expected);
    // Generated again from the inferred grammar and its meshes: the same objects.
    r = run_program("generate", {stem + ".grm", "-o", stem + "_again.obj"}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.err.find("unknown primitive"), std::string::npos) << r.err;
    EXPECT_EQ(object_lines(read_file(dir / (stem + "_again.obj"))), written);
  }
}

// A glTF node "#wall" from another tool: its mesh goes into the meshes
// file under a name OBJ keeps ("%23wall", not a comment), and generate
// finds it there.
TEST(InferCli, ANodeNamedWithAHashKeepsItsMesh) {
  TempFolder dir;
  std::string gltf = read_file(VERN_SOURCE_DIR "/tests/bad_inputs/gltf/two_parts.gltf");
  gltf.replace(gltf.find("\"wall\""), 6, "\"#wall\"");
  write_text(dir / "hash.gltf", gltf);
  auto r = run_program("infer", {"hash.gltf", "-o", "hash.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_file(dir / "hash.grm").find("I(\"#wall\")"), std::string::npos) << read_file(dir / "hash.grm");
  EXPECT_NE(read_file(dir / "hash.prims.obj").find("\no %23wall\n"), std::string::npos);
  r = run_program("generate", {"hash.grm", "-o", "out.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("unknown primitive"), std::string::npos) << r.err;
  EXPECT_NE(read_file(dir / "out.obj").find("\no %23wall\n"), std::string::npos);
}

// generate follows a grammar's @primitives only into the grammar's own
// folder: infer says so when it writes the meshes elsewhere.
TEST(InferCli, MeshesOutsideTheGrammarsFolderNeedAllowOutsideFiles) {
  TempFolder dir;
  fs::create_directories(dir / "grammars");
  fs::create_directories(dir / "meshes");
  auto r = run_program("infer", {kExamples + "garage", "-o", "grammars/garage.grm", "--primitives-out",
                                 "meshes/garage.prims.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("infer: warning: the grammar names its meshes as '../meshes/garage.prims.obj', outside its "
                       "folder: generate reads them only with --allow-outside-files"),
            std::string::npos)
      << r.err;
  r = run_program("generate", {"grammars/garage.grm", "-o", "out.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("@primitives names '../meshes/garage.prims.obj', which is outside the grammar's folder"),
            std::string::npos)
      << r.err;
  r = run_program("generate", {"grammars/garage.grm", "--allow-outside-files", "-o", "out.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  // Beside the grammar (the default), nothing to say.
  r = run_program("infer", {kExamples + "garage", "-o", "grammars/beside.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

// A block of 0.1 m bricks beside a 40 m house: @scope draws up to 80 m
// on each axis, so a test building of the brick alternative runs past a
// million parts. The grammar derives both examples: infer writes it and
// says so, where it used to stop with derive's error and no grammar.
TEST(InferCli, TestBuildingsPastALimitAreAWarningAndTheGrammarIsWritten) {
  TempFolder dir;
  write_text(dir / "block.grm", "b --> repeat(x, 0.1){ repeat(y, 0.1){ repeat(z, 0.1){ I(brick) } } }\n");
  write_text(dir / "house.grm", "h --> split(x){ ~1 : I(wall) | ~1 : I(roof) }\n");
  auto r = run_program("generate", {"block.grm", "--scope", "0.4", "0.4", "0.4", "-q", "-o", "block.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_program("generate", {"house.grm", "--scope", "40", "40", "40", "-q", "-o", "house.obj"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_program("infer", {"block.obj", "house.obj", "-o", "style.grm"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("stops at a limit: more than 1000000 terminals in one derivation; the largest example has "
                       "64 parts"),
            std::string::npos)
      << r.err;
  r = run_program("check", {"style.grm", "block.obj", "house.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("2 of 2 examples derivable"), std::string::npos) << r.out;
}

// Halls of five to eight storeys: merged, a hall of five reaches its odd
// storey through a free combination of two choices, a split whose lengths
// were noted from the other halls only. Drawn in metres from those, that
// storey's height (3.1 m) fell outside its range and infer stopped with
// "no grammar inferred derives"; it now merges once more, the varying
// sizes kept as shares, and every hall checks.
TEST(InferCli, AnExampleReachedThroughAFreeCombinationKeepsItsSizes) {
  TempFolder dir;
  const std::string style = VERN_SOURCE_DIR "/tests/data/hall_of_paired_storeys.grm";
  std::vector<std::string> examples;
  for (const int seed : {13, 15, 26, 27, 28, 29, 30}) {
    examples.push_back("hall" + std::to_string(seed) + ".obj");
    const auto r = run_program("generate", {style, "--seed", std::to_string(seed), "-q", "-o", examples.back()}, dir.path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  std::vector<std::string> args = examples;
  args.insert(args.end(), {"-o", "halls.grm"});
  auto r = run_program("infer", args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  args = examples;
  args.insert(args.begin(), "halls.grm");
  r = run_program("check", args, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("7 of 7 examples derivable"), std::string::npos) << r.out;
}

// Houses modelled as people model them: windows set into a wall that is
// one box. Each wall is cut around its windows (layered_parts.hpp), with
// no flag; check takes the houses the same way.
TEST(InferCli, WindowsSetIntoAWallInferAndCheckAsTheyAre) {
  using test::part;
  TempFolder dir;
  std::vector<std::string> houses;
  for (const int bays : {2, 3, 4}) {
    const double width = 3.3 * bays;
    std::vector<LabelledBox> boxes = {part("wall", {0, 0, 0}, {width, 0.3, 6}), part("roof", {0, 0, 6}, {width, 0.3, 7})};
    for (int i = 0; i < bays; ++i)
      for (const double z : {1.0, 4.0})
        boxes.push_back(part("window", {3.3 * i + 1, 0, z}, {3.3 * i + 2.3, 0.3, z + 1.2}));
    houses.push_back("house" + std::to_string(bays) + ".obj");
    write_text(dir / houses.back(), test::boxes_obj(boxes));
  }
  std::vector<std::string> args = houses;
  args.insert(args.end(), {"-o", "houses.grm"});
  auto r = run_program("infer", args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string grammar = read_file(dir / "houses.grm");
  EXPECT_NE(grammar.find("I(wall)"), std::string::npos) << grammar;
  args = houses;
  args.insert(args.begin(), "houses.grm");
  r = run_program("check", args, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("3 of 3 examples derivable"), std::string::npos) << r.out;
}

// Facades annotated by hand: a wall with rows and columns of windows, every
// window edge off by up to 12 mm (a pixel or so). As read, no two windows
// line up and nothing repeats: an alternative per facade. With the noise
// level given (--tolerance 0.03), coordinates within it are one place, the
// rows and bays repeat, the three facades are one building rule, and check
// derives each facade as annotated, saying how far its coordinates moved.
TEST(InferCli, FacadesAnnotatedWithNoiseInferAsRepeatsWithinTheNoiseLevel) {
  using test::part;
  TempFolder dir;
  std::mt19937_64 rng(61208);
  std::uniform_real_distribution<double> noise(-0.012, 0.012);
  std::vector<std::string> facades;
  for (const auto& [columns, rows] : {std::pair{4, 5}, std::pair{5, 6}, std::pair{6, 7}}) {
    std::vector<LabelledBox> boxes = {part("facade", {0, 0, 0}, {3.0 * columns, 0.2, 3.2 * rows})};
    for (int c = 0; c < columns; ++c)
      for (int r = 0; r < rows; ++r)
        boxes.push_back(part("window", {3.0 * c + 1 + noise(rng), 0, 3.2 * r + 1 + noise(rng)},
                             {3.0 * c + 2.2 + noise(rng), 0.2, 3.2 * r + 2.5 + noise(rng)}));
    facades.push_back("facade" + std::to_string(columns) + ".obj");
    write_text(dir / facades.back(), "# up z\n" + test::boxes_obj(boxes));
  }
  auto infer_with = [&](std::vector<std::string> args, const std::string& out) {
    args.insert(args.begin(), facades.begin(), facades.end());
    args.insert(args.end(), {"-o", out, "-q"});
    const auto r = run_program("infer", args, dir.path());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_file(dir / out);
  };
  auto count = [](const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
  };
  const std::string as_read = infer_with({}, "as_read.grm");
  EXPECT_EQ(count(as_read, "building -->"), 3u) << as_read;
  const std::string snapped = infer_with({"--tolerance", "0.03"}, "snapped.grm");
  EXPECT_EQ(count(snapped, "building -->"), 1u) << snapped;
  EXPECT_NE(snapped.find("repeat(z"), std::string::npos) << snapped;
  EXPECT_NE(snapped.find("repeat(x"), std::string::npos) << snapped;
  std::vector<std::string> args = facades;
  args.insert(args.begin(), "snapped.grm");
  args.insert(args.end(), {"--tolerance", "0.03"});
  const auto r = run_program("check", args, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("3 of 3 examples derivable"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("coordinates moved by up to 0.0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" m onto places within the noise level 0.03 m"), std::string::npos) << r.out;
}

// Houses standing at an angle about z, their windows set into their walls:
// each is read turned back, in its own frame (the same grammar as from the
// houses along the axes), and said; check derives them. Read as they
// stood, their parts' boxes overlapped and they were refused.
TEST(InferCli, HousesStandingAtAnAngleAreReadInTheirOwnFrame) {
  using test::part;
  TempFolder dir;
  std::vector<std::string> along, turned;
  for (const int bays : {2, 3, 4}) {
    const double width = 2.4 * bays;
    std::vector<LabelledBox> boxes = {part("wall", {0, 0, 0}, {width, 5, 3}), part("roof", {0, 0, 3}, {width, 5, 4.5})};
    for (int i = 0; i < bays; ++i) boxes.push_back(part("window", {2.4 * i + 0.7, 0, 1}, {2.4 * i + 1.7, 0.2, 2.2}));
    along.push_back("along" + std::to_string(bays) + ".obj");
    turned.push_back("turned" + std::to_string(bays) + ".obj");
    write_text(dir / along.back(), test::boxes_obj(boxes));
    write_text(dir / turned.back(), test::boxes_obj(boxes, (10.0 + 12 * bays) * std::numbers::pi / 180));
  }
  auto infer_from = [&](std::vector<std::string> files, const std::string& out) {
    files.insert(files.end(), {"-o", out});
    return run_program("infer", files, dir.path());
  };
  ASSERT_EQ(infer_from(along, "along.grm").exit_code, 0);
  const auto r = infer_from(turned, "turned.grm");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("note: turned2.obj stands turned 34 degrees about z: read turned back"), std::string::npos)
      << r.err;
  EXPECT_EQ(grammar_body(dir / "turned.grm"), grammar_body(dir / "along.grm"));
  std::vector<std::string> args = turned;
  args.insert(args.begin(), "along.grm");
  const auto c = run_program("check", args, dir.path());
  EXPECT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("3 of 3 examples derivable"), std::string::npos) << c.out;
}

// Sills painted over the windows' lower edges: with no order every file
// with such a pair is named, not the first alone; --stack settles them
// for infer and check alike.
TEST(InferCli, OverlapsWithoutAStackOrderAreNamedForEveryFile) {
  using test::part;
  TempFolder dir;
  for (const int k : {0, 1}) {
    const double w = 4 + k;
    write_text(dir / ("facade" + std::to_string(k) + ".obj"),
               test::boxes_obj({part("facade", {0, 0, 0}, {w, 0.2, 3}), part("window", {1, 0, 1}, {2, 0.2, 2}),
                                part("sill", {0.9, 0, 0.9}, {2.1, 0.2, 1.1})}));
  }
  auto r = run_program("infer", {"facade0.obj", "facade1.obj", "-o", "f.grm"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.err;
  for (const std::string file : {"facade0.obj", "facade1.obj"})
    EXPECT_NE(r.err.find(file + ":17:1: error: objects 'window' (line 17) and 'sill' (line 32) overlap by 1 x 0.2 x 0.1"),
              std::string::npos)
        << r.err;
  EXPECT_FALSE(fs::exists(dir / "f.grm"));
  r = run_program("infer", {"facade0.obj", "facade1.obj", "-o", "f.grm", "--stack", "facade,window,sill"}, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = run_program("check", {"f.grm", "facade0.obj", "facade1.obj", "--stack", "facade,window,sill"}, dir.path());
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  r = run_program("check", {"f.grm", "facade0.obj"}, dir.path());
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  EXPECT_NE(r.err.find("--stack window,sill"), std::string::npos) << r.err;
}

TEST(InferCli, UsageErrors) {
  auto r = run_program("infer", {kExamples + "garage"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no output grammar given"), std::string::npos);
  r = run_program("infer", {"-o", "x.grm"});
  EXPECT_EQ(r.exit_code, 2);
  r = run_program("infer", {"--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("usage: infer EXAMPLES"), std::string::npos);
  // An option's help of several lines keeps to its column.
  EXPECT_NE(r.out.find("examples: apart (default), each\n                            building standing apart"),
            std::string::npos)
      << r.out;
  r = run_program("infer", {"x.obj", "-o", "x.grm", "--buildings", "streets"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--buildings"), std::string::npos) << r.err;
  r = run_program("check", {"only.grm"});
  EXPECT_EQ(r.exit_code, 2);
}

// Every command says its version, the one the build's project() gives,
// and does nothing else.
TEST(InferCli, EveryCommandSaysItsVersion) {
  for (const std::string command : {"infer", "check", "generate", "evaluate"}) {
    const auto r = run_program(command, {"--version"});
    EXPECT_EQ(r.exit_code, 0) << command << r.err;
    EXPECT_TRUE(std::regex_match(r.out, std::regex(command + " \\(Vernacular\\) [0-9]+\\.[0-9]+\\.[0-9]+\n")))
        << command << ": " << r.out;
    EXPECT_EQ(r.err, "") << command;
  }
}

TEST(InferCli, BadExamplesAreRefusedAndNothingIsWritten) {
  TempFolder dir;
  write_text(dir / "empty.obj", "");
  write_text(dir / "binary.obj", std::string("\x7f" "ELF\x02\x01\x01\0\0\0", 10));
  write_text(dir / "overlap.obj",
             "o wall\nv 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 2 0 1\nv 2 1 1\nv 0 1 1\nf 1 2 3 4\nf 5 6 7 8\n"
             "o door\nv 1 0 0\nv 3 0 0\nv 3 1 0\nv 1 1 0\nv 1 0 1\nv 3 0 1\nv 3 1 1\nv 1 1 1\nf 9 10 11 12\nf 13 14 15 16\n");
  for (const std::string bad : {"empty.obj", "binary.obj", "overlap.obj", "missing.obj"}) {
    SCOPED_TRACE(bad);
    const auto r = run_program("infer", {bad, "-o", "style.grm"}, dir.path());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;  // the message names the file
    EXPECT_FALSE(std::filesystem::exists(dir / "style.grm"));
    EXPECT_FALSE(std::filesystem::exists(dir / "style.prims.obj"));
  }
  const auto r = run_program("infer", {"overlap.obj", "-o", "style.grm"}, dir.path());
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("wall"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("door"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vern

namespace vern {
namespace {

// Two flat panels side by side in the plane x = 0, each a grid of about
// a million triangles: every vertex has the same x.
void write_two_dense_panels(const std::filesystem::path& path, int n) {
  std::ofstream out(path, std::ios::binary);
  std::string text;
  const int row = n + 1;
  for (int panel = 0; panel < 2; ++panel) {
    const int base = panel * row * row;
    text += "o panel\n";
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        text += "v 0 " + std::to_string(panel + double(i) / n) + " " + std::to_string(double(j) / n) + "\n";
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const int a = base + i * row + j + 1, b = a + row, c = b + 1, d = a + 1;
        text += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) + "\nf " +
                std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) + "\n";
      }
    out << text;
    text.clear();
  }
}

// Matching a part's vertices against its label's mesh looked at every
// vertex with about the same x for each vertex: a million-face panel took
// minutes. Now linear: seconds (the bound leaves room for the sanitizers).
TEST(InferCli, AMillionFacesAPartInferInLinearTime) {
  TempFolder dir;
  write_two_dense_panels(dir / "panels.obj", 707);  // 999 698 triangles each
  const auto started = std::chrono::steady_clock::now();
  const auto r = run_program("infer", {"panels.obj", "-j", "1", "-q", "-o", "style.grm"}, dir.path());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_LT(seconds, 60.0);
}

}  // namespace
}  // namespace vern
