// Reports as one HTML file: everything inside it, text shown as written.
#include "report/html_report.hpp"

#include <gtest/gtest.h>

#include <regex>

#include "io/gltf_container.hpp"

namespace vern {
namespace {

Report sample() {
  Report r;
  r.title = "style <b>.grm";
  r.intro = "A & B";
  r.table_head = {"grammar", "rules"};
  r.table_rows = {{"a.grm", "12"}};
  ReportSection s;
  s.heading = "a.grm";
  s.figures = {{"rules", "12"}};
  s.notes = {"x.obj:3:1: warning: 'a' <and> 'b'"};
  ReportGallery g;
  g.title = "Examples";
  g.pictures.push_back({"house \"1\".obj", std::string("\x89PNG\r\n\x1a\nA", 9), 4, 3});
  g.pictures.push_back({"house 2.obj", std::string("\x89PNG\r\n\x1a\nB", 9), 4, 3});
  s.galleries.push_back(g);
  s.grammar_name = "a.grm";
  s.grammar_text = "building --> split(x){ ~1 : I(\"</pre><script>x</script>\") }\n# second line\n";
  r.sections.push_back(s);
  return r;
}

TEST(HtmlReport, TextIsEscapedAndShownAsWritten) {
  const std::string html = report_html(sample());
  EXPECT_EQ(html.find("<b>"), std::string::npos);
  EXPECT_EQ(html.find("<script>"), std::string::npos);
  EXPECT_NE(html.find("style &lt;b&gt;.grm"), std::string::npos);
  EXPECT_NE(html.find("I(&quot;&lt;/pre&gt;&lt;script&gt;x&lt;/script&gt;&quot;)"), std::string::npos);
  EXPECT_NE(html.find("A &amp; B"), std::string::npos);
  EXPECT_NE(html.find("house &quot;1&quot;.obj"), std::string::npos);
  // Each line of the grammar numbered.
  EXPECT_NE(html.find("<span class=\"ln\">1</span>building"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"ln\">2</span># second line"), std::string::npos);
  EXPECT_EQ(html.find("<span class=\"ln\">3</span>"), std::string::npos);
}

TEST(HtmlReport, PastThreeNotesTheRestFoldAway) {
  Report r = sample();
  EXPECT_EQ(report_html(r).find("<details><summary>"), std::string::npos);
  r.sections[0].notes = {"one", "two", "three", "four", "five"};
  const std::string html = report_html(r);
  const std::size_t fold = html.find("<details><summary>2 more</summary>");
  ASSERT_NE(fold, std::string::npos) << html;
  EXPECT_LT(html.find(">three</p>"), fold);
  EXPECT_GT(html.find(">four</p>"), fold);
  EXPECT_GT(html.find(">five</p>"), fold);
}

TEST(HtmlReport, PicturesAreInsideTheFileAndNothingIsFetched) {
  const std::string html = report_html(sample());
  const std::regex src("src=\"([^\"]*)\"");
  std::size_t pictures = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), src); it != std::sregex_iterator(); ++it) {
    const std::string value = (*it)[1];
    ASSERT_EQ(value.rfind("data:image/png;base64,", 0), 0u) << value;
    ++pictures;
  }
  EXPECT_EQ(pictures, 2u);
  EXPECT_NE(html.find(base64(std::string("\x89PNG\r\n\x1a\nB", 9))), std::string::npos);
  EXPECT_EQ(html.find("href="), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("</html>"), std::string::npos);
}

}  // namespace
}  // namespace vern
