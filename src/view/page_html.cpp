// The pages of kvd view: web/viewer.html (triangles) and web/segments.html
// (segments) with their assets and data inlined.
#include <stdexcept>

#include "page_data.hpp"
#include "segment_page.hpp"

namespace kvd::view {

namespace assets {
// Generated from web/ (and, for the triangle page, Debian's libjs-three) by
// cmake/embed_assets.cmake.
extern const char* const style;
extern const char* const segment_page;
extern const char* const segment_script;
#ifdef KVD_HAVE_VIEWER
extern const char* const page;
extern const char* const viewer;
extern const char* const three;
extern const char* const orbit;
#endif
}  // namespace assets

namespace {

void replace(std::string& s, const std::string& marker, const std::string& with) {
  const auto at = s.find(marker);
  if (at == std::string::npos) throw std::logic_error("the page has no " + marker);
  s.replace(at, marker.size(), with);
}

// Inside <script> the text "</" could end the element, and "<!--" would
// let a later "<script" hide its end: JSON may write them "<\/" and
// "\u003c!--" (in JSON, '<' is only ever inside a string).
std::string script_safe(std::string s) {
  for (std::size_t at = 0; (at = s.find("</", at)) != std::string::npos; at += 3) s.replace(at, 2, "<\\/");
  for (std::size_t at = 0; (at = s.find("<!--", at)) != std::string::npos; at += 9) s.replace(at, 1, "\\u003c");
  return s;
}

std::string json_text(const nlohmann::json& data) {
  return script_safe(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

}  // namespace

std::string segment_page_html(const nlohmann::json& data) {
  std::string page = assets::segment_page;
  // In order: the data and the script hold no markers of their own.
  replace(page, "/*KVD_STYLE*/", assets::style);
  replace(page, "/*KVD_SEGMENTS*/", assets::segment_script);
  replace(page, "/*KVD_DATA*/", json_text(data));
  return page;
}

#ifdef KVD_HAVE_VIEWER
std::string page_html(const nlohmann::json& data) {
  std::string page = assets::page;
  // In order: the data and the viewer hold no markers of their own.
  replace(page, "/*KVD_STYLE*/", assets::style);
  replace(page, "/*KVD_THREE*/", assets::three);
  replace(page, "/*KVD_ORBIT*/", assets::orbit);
  replace(page, "/*KVD_VIEWER*/", assets::viewer);
  replace(page, "/*KVD_DATA*/", json_text(data));
  return page;
}

bool page_supported() { return true; }
#else
std::string page_html(const nlohmann::json&) { throw std::logic_error("this build has no viewer page"); }
bool page_supported() { return false; }
#endif

}  // namespace kvd::view
