// Decodes a PNG with libpng's simplified reader (not zdg's writer code): the independent
// reader of the picture tests.
//
//   const RgbImage img = zdg::test::decode_png(dir / "a.png");
#pragma once

#include <zdg/kernel/render/picture.hpp>

#include <gtest/gtest.h>
#include <png.h>

#include <filesystem>

namespace zdg::test {

inline RgbImage decode_png(const std::filesystem::path& p) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  EXPECT_NE(png_image_begin_read_from_file(&png, p.c_str()), 0) << png.message;
  png.format = PNG_FORMAT_RGB;
  RgbImage img(static_cast<int>(png.width), static_cast<int>(png.height));
  EXPECT_NE(png_image_finish_read(&png, nullptr, img.rgb.data(), 0, nullptr), 0) << png.message;
  return img;
}

} // namespace zdg::test
