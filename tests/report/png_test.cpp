// PNG files of pictures: what is written reads back the same, the same
// picture is the same bytes, and what is no PNG is said to be none.
#include "report/png.hpp"

#include <gtest/gtest.h>

#include "base/error.hpp"

namespace vern {
namespace {

RgbImage gradient(int width, int height) {
  RgbImage image;
  image.width = width;
  image.height = height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      image.rgb.push_back(static_cast<std::uint8_t>(x * 255 / width));
      image.rgb.push_back(static_cast<std::uint8_t>(y * 255 / height));
      image.rgb.push_back(static_cast<std::uint8_t>((x * y) % 256));
    }
  return image;
}

TEST(Png, APictureReadsBackPixelForPixel) {
  const RgbImage image = gradient(37, 21);
  const std::string bytes = png_bytes(image);
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  EXPECT_EQ(read_png(bytes), image);
  // No time stamp or other run-dependent chunk: the same bytes again.
  EXPECT_EQ(png_bytes(image), bytes);
  EXPECT_EQ(bytes.find("tIME"), std::string::npos);
}

TEST(Png, BytesThatAreNoPngAreAnInputError) {
  try {
    read_png("GIF89a not a png");
    FAIL() << "read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Input);
    EXPECT_NE(std::string(e.what()).find("not a PNG"), std::string::npos) << e.what();
  }
}

TEST(Png, AnImageWhosePixelsDoNotMatchItsSizeIsABug) {
  RgbImage image = gradient(4, 4);
  image.rgb.pop_back();
  EXPECT_THROW(png_bytes(image), Error);
}

}  // namespace
}  // namespace vern
