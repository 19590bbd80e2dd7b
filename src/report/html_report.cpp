#include "report/html_report.hpp"

#include "io/gltf_container.hpp"

namespace vern {

namespace {

// Plain, readable on a phone and on paper; pictures in a grid that wraps.
constexpr const char* kStyle = R"(body{font:15px/1.45 system-ui,sans-serif;margin:2em auto;max-width:1200px;padding:0 1em;color:#222}
h1{font-size:1.6em;margin-bottom:.2em}h2{margin-top:1.8em;border-bottom:1px solid #ccc}h3{font-size:1.05em;margin:1.2em 0 .4em}
table{border-collapse:collapse;margin:.6em 0}td,th{padding:.2em .8em;border-bottom:1px solid #e4e4e4;text-align:left;vertical-align:top}
th{background:#f4f4f4}td.n{text-align:right;font-variant-numeric:tabular-nums}
.gallery{display:flex;flex-wrap:wrap;gap:10px}figure{margin:0;border:1px solid #ddd;background:#fff}
figure img{display:block;max-width:100%;height:auto}figcaption{font-size:.85em;padding:.2em .5em;color:#555;max-width:360px;overflow-wrap:anywhere}
.note{background:#fff7e0;border-left:4px solid #e0b040;padding:.4em .8em;white-space:pre-wrap;font-family:ui-monospace,monospace;font-size:.85em}
pre{background:#f7f7f7;border:1px solid #e4e4e4;padding:.6em;overflow:auto;font-size:.85em;line-height:1.35}
pre .ln{color:#999;user-select:none;display:inline-block;min-width:3.5em;text-align:right;padding-right:1em}
details summary{cursor:pointer;font-weight:600})";

bool numeric(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || c == '.' || c == '-' || c == '+' || c == ',' || c == ' ' || c == '%' || c == '/'))
      return false;
  return true;
}

void cell(std::string& out, const char* tag, std::string_view text) {
  out += '<';
  out += tag;
  if (std::string_view(tag) == "td" && numeric(text)) out += " class=\"n\"";
  out += '>';
  out += html_escaped(text);
  out += "</";
  out += tag;
  out += '>';
}

void grammar_listing(std::string& out, const ReportSection& s) {
  out += "<details open><summary>";
  out += html_escaped(s.grammar_name.empty() ? "Grammar" : s.grammar_name);
  out += "</summary><pre>";
  std::size_t line = 1, from = 0;
  while (from < s.grammar_text.size()) {
    std::size_t end = s.grammar_text.find('\n', from);
    if (end == std::string::npos) end = s.grammar_text.size();
    out += "<span class=\"ln\">" + std::to_string(line++) + "</span>";
    out += html_escaped(std::string_view(s.grammar_text).substr(from, end - from));
    out += '\n';
    from = end + 1;
  }
  out += "</pre></details>\n";
}

}  // namespace

std::string html_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string report_html(const Report& report) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                    "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>";
  out += html_escaped(report.title);
  out += "</title>\n<style>";
  out += kStyle;
  out += "</style></head>\n<body>\n<h1>" + html_escaped(report.title) + "</h1>\n";
  if (!report.intro.empty()) out += "<p>" + html_escaped(report.intro) + "</p>\n";
  if (!report.table_head.empty()) {
    out += "<table><tr>";
    for (const std::string& h : report.table_head) cell(out, "th", h);
    out += "</tr>\n";
    for (const auto& row : report.table_rows) {
      out += "<tr>";
      for (const std::string& c : row) cell(out, "td", c);
      out += "</tr>\n";
    }
    out += "</table>\n";
  }
  for (const ReportSection& s : report.sections) {
    if (!s.heading.empty()) out += "<h2>" + html_escaped(s.heading) + "</h2>\n";
    if (!s.figures.empty()) {
      out += "<table>";
      for (const auto& [name, value] : s.figures) {
        out += "<tr>";
        cell(out, "th", name);
        cell(out, "td", value);
        out += "</tr>";
      }
      out += "</table>\n";
    }
    // Past three, notes fold away: forty warnings would push the pictures
    // off the first screen.
    constexpr std::size_t kNotesShown = 3;
    for (std::size_t i = 0; i < s.notes.size(); ++i) {
      if (i == kNotesShown)
        out += "<details><summary>" + std::to_string(s.notes.size() - kNotesShown) + " more</summary>\n";
      out += "<p class=\"note\">" + html_escaped(s.notes[i]) + "</p>\n";
    }
    if (s.notes.size() > kNotesShown) out += "</details>\n";
    for (const ReportGallery& g : s.galleries) {
      out += "<h3>" + html_escaped(g.title) + "</h3>\n<div class=\"gallery\">\n";
      for (const ReportPicture& p : g.pictures) {
        out += "<figure><img alt=\"" + html_escaped(p.caption) + "\" width=\"" + std::to_string(p.width) +
               "\" height=\"" + std::to_string(p.height) + "\" src=\"data:image/png;base64,";
        out += base64(p.png);
        out += "\"><figcaption>" + html_escaped(p.caption) + "</figcaption></figure>\n";
      }
      out += "</div>\n";
    }
    if (!s.grammar_text.empty()) grammar_listing(out, s);
  }
  out += "<p style=\"color:#888;font-size:.8em\">Written by Vernacular. Pictures: parallel projection from the "
         "front left, each part in the colour the written meshes give its label.</p>\n</body></html>\n";
  return out;
}

}  // namespace vern
