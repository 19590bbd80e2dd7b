#include "report/png.hpp"

#include <png.h>

#include <cstring>

#include "base/error.hpp"

namespace vern {

namespace {

png_image image_header(const RgbImage& image) {
  png_image header;
  std::memset(&header, 0, sizeof header);
  header.version = PNG_IMAGE_VERSION;
  header.width = static_cast<png_uint_32>(image.width);
  header.height = static_cast<png_uint_32>(image.height);
  header.format = PNG_FORMAT_RGB;
  return header;
}

}  // namespace

std::string png_bytes(const RgbImage& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
    throw Error(ErrorKind::Internal, "png_bytes: the image's pixels do not match its size");
  // libpng's simplified API: one call to size the file, one to write it.
  png_image header = image_header(image);
  png_alloc_size_t size = 0;
  if (!png_image_write_to_memory(&header, nullptr, &size, 0, image.rgb.data(), 0, nullptr))
    throw Error(ErrorKind::Internal, std::string("libpng could not size a PNG: ") + header.message);
  std::string bytes(size, '\0');
  header = image_header(image);
  if (!png_image_write_to_memory(&header, bytes.data(), &size, 0, image.rgb.data(), 0, nullptr))
    throw Error(ErrorKind::Internal, std::string("libpng could not write a PNG: ") + header.message);
  bytes.resize(size);
  return bytes;
}

RgbImage read_png(std::string_view bytes) {
  png_image header;
  std::memset(&header, 0, sizeof header);
  header.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&header, bytes.data(), bytes.size()))
    throw Error(ErrorKind::Input, std::string("not a PNG file: ") + header.message);
  header.format = PNG_FORMAT_RGB;
  RgbImage image;
  image.width = static_cast<int>(header.width);
  image.height = static_cast<int>(header.height);
  image.rgb.resize(PNG_IMAGE_SIZE(header));
  if (!png_image_finish_read(&header, nullptr, image.rgb.data(), 0, nullptr)) {
    png_image_free(&header);
    throw Error(ErrorKind::Input, std::string("a PNG file that does not read: ") + header.message);
  }
  return image;
}

}  // namespace vern
