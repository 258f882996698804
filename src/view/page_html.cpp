// The page of kvd view: web/viewer.html with its assets and data inlined.
#include <stdexcept>

#include "page_data.hpp"

namespace kvd::view {

#ifdef KVD_HAVE_VIEWER
namespace assets {
// Generated from web/ and Debian's libjs-three by cmake/embed_assets.cmake.
extern const char* const page;
extern const char* const style;
extern const char* const viewer;
extern const char* const three;
extern const char* const orbit;
}  // namespace assets

namespace {

void replace(std::string& s, const std::string& marker, const std::string& with) {
  const auto at = s.find(marker);
  if (at == std::string::npos) throw std::logic_error("web/viewer.html has no " + marker);
  s.replace(at, marker.size(), with);
}

// Inside <script> the text "</" could end the element: JSON may write it "<\/".
std::string script_safe(std::string s) {
  for (std::size_t at = 0; (at = s.find("</", at)) != std::string::npos; at += 3) s.replace(at, 2, "<\\/");
  return s;
}

}  // namespace

std::string page_html(const nlohmann::json& data) {
  std::string page = assets::page;
  // In order: the data and the viewer hold no markers of their own.
  replace(page, "/*KVD_STYLE*/", assets::style);
  replace(page, "/*KVD_THREE*/", assets::three);
  replace(page, "/*KVD_ORBIT*/", assets::orbit);
  replace(page, "/*KVD_VIEWER*/", assets::viewer);
  replace(page, "/*KVD_DATA*/", script_safe(data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
  return page;
}

bool page_supported() { return true; }
#else
std::string page_html(const nlohmann::json&) { throw std::logic_error("this build has no viewer page"); }
bool page_supported() { return false; }
#endif

}  // namespace kvd::view
