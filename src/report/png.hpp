// PNG files of pictures, with Debian's libpng.
//
// Written without a time stamp or any other chunk that changes from run to
// run, so that the same picture is the same bytes.
#pragma once

#include <string>
#include <string_view>

#include "report/raster.hpp"

namespace vern {

// The image as the bytes of a PNG file (8-bit RGB, no interlace).
// Throws vern::Error (Internal) if libpng fails.
std::string png_bytes(const RgbImage& image);

// A PNG file's pixels as 8-bit RGB (any PNG libpng reads: palettes, grey,
// 16 bits and alpha are converted, alpha dropped). Throws vern::Error
// (Input) for bytes that are no PNG, saying so.
RgbImage read_png(std::string_view bytes);

}  // namespace vern
