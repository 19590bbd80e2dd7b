// Reports: one HTML file that shows a run, to open in any browser or mail.
//
// Everything is inside the file (pictures as PNG data URIs, the style sheet
// inline, no script, nothing fetched), so it shows the same offline, in a
// mail client that blocks what is remote, and years later. `infer
// --report` writes one of a style (its examples beside new buildings of
// the grammar inferred, the grammar, its figures), `evaluate --report` one
// of each grammar it round-trips.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace vern {

struct ReportPicture {
  std::string caption;  // under the picture; also its alt text
  std::string png;      // the PNG file's bytes (report/png.hpp)
  int width = 0, height = 0;
};

struct ReportGallery {
  std::string title;  // "Examples", "New buildings (seeds 1 to 8)"
  std::vector<ReportPicture> pictures;
};

struct ReportSection {
  std::string heading;
  std::vector<std::pair<std::string, std::string>> figures;  // name, value, as a two-column table
  std::vector<std::string> notes;                             // warnings and remarks, one paragraph each
  std::vector<ReportGallery> galleries;
  std::string grammar_name;  // the grammar shown with numbered lines, when its text is not empty
  std::string grammar_text;
};

struct Report {
  std::string title;
  std::string intro;  // a paragraph under the title
  // A table across sections (evaluate's one row a grammar); none when empty.
  std::vector<std::string> table_head;
  std::vector<std::vector<std::string>> table_rows;
  std::vector<ReportSection> sections;
};

// The report as a complete HTML5 document (UTF-8). Text is escaped: a
// grammar holding "</pre>" or a label "<b>" shows as written.
std::string report_html(const Report& report);

// Text safe inside HTML elements and attribute values.
std::string html_escaped(std::string_view text);

}  // namespace vern
