// The page's files: a fixed list, and no URL ever reaches outside it.
#include "serve/web_files.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"

namespace vern {
namespace {

TEST(WebFiles, ThePagesFilesAreServedFromItsFolder) {
  const auto index = web_file("/", "/srv/web");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->path, std::filesystem::path("/srv/web/index.html"));
  EXPECT_EQ(index->content_type, "text/html; charset=utf-8");
  const auto three = web_file("/vendor/three.module.js", "/srv/web");
  ASSERT_TRUE(three);
  EXPECT_EQ(three->path, std::filesystem::path("/srv/web/node_modules/three/build/three.module.js"));
  EXPECT_EQ(web_file("/app.js", "/srv/web")->content_type, "text/javascript; charset=utf-8");
}

TEST(WebFiles, NoOtherUrlNamesAFile) {
  for (const char* url : {"/../etc/passwd", "/%2e%2e/etc/passwd", "/node_modules/three/package.json", "/vendor/",
                          "/vendor/../index.html", "//etc/passwd", "/index.html/", "/APP.JS", "", "/app.js?x=1",
                          "/package.json", "/editor.js/../../secret"})
    EXPECT_FALSE(web_file(url, "/srv/web")) << url;
}

TEST(WebFiles, AFolderWithoutThePageIsRefusedSayingHowToSetItUp) {
  try {
    find_web_folder(std::filesystem::path("/nonexistent/web"), "/proc/self/exe");
    FAIL() << "found";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("scripts/setup"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vern
