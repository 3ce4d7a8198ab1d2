// PngIoTest: PNG through libpng. Round trips for every channel count, every PNG colour type and
// bit depth read exactly as the OpenImageIO module reads it (the independent check that moving
// PNG off OIIO changed no pixel), corrupt files give one-line errors, EXR goes through the module.
// No GL context needed.
#include <algorithm>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>

#include "image/image.h"
#include "image/image_io_internal.h"
#include "image_test_util.h"

namespace ps {
namespace {

namespace fs = std::filesystem;

// A PNG written with libpng directly, in a layout write_image never produces (palette, 16 bit,
// low-bit gray, tRNS, interlace). Samples are a fixed byte pattern, so every value is exercised.
struct RawPng {
  int color_type = PNG_COLOR_TYPE_RGB;
  int bit_depth = 8;
  bool trns = false;
  bool interlaced = false;
  int width = 13, height = 7;  // odd, non-square: catches stride and sub-byte packing bugs
};

std::string describe(const RawPng& s) {
  return "type" + std::to_string(s.color_type) + "_" + std::to_string(s.bit_depth) + "bit" +
         (s.trns ? "_trns" : "") + (s.interlaced ? "_adam7" : "");
}

int file_channels(int color_type) {
  switch (color_type) {
    case PNG_COLOR_TYPE_GRAY_ALPHA: return 2;
    case PNG_COLOR_TYPE_RGB: return 3;
    case PNG_COLOR_TYPE_RGBA: return 4;
    default: return 1;  // gray, palette index
  }
}

std::vector<png_byte> sample_bytes(const RawPng& s) {
  const size_t row_bytes = (static_cast<size_t>(s.width) * file_channels(s.color_type) * s.bit_depth + 7) / 8;
  std::vector<png_byte> bytes(row_bytes * s.height);
  for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<png_byte>(i * 97 + (i >> 8) * 31 + 5);
  return bytes;
}

// Returns false if libpng refused; every object with a destructor exists before the setjmp.
bool write_raw_png(const fs::path& path, const RawPng& s) {
  std::vector<png_byte> bytes = sample_bytes(s);
  const size_t row_bytes = bytes.size() / s.height;
  std::vector<png_bytep> rows;
  for (int y = 0; y < s.height; ++y) rows.push_back(bytes.data() + y * row_bytes);
  const int entries = 1 << std::min(s.bit_depth, 8);
  std::vector<png_color> palette(entries);
  std::vector<png_byte> alpha(entries);
  for (int i = 0; i < entries; ++i) {
    palette[i] = {static_cast<png_byte>(i * 37), static_cast<png_byte>(255 - i * 11),
                  static_cast<png_byte>(i * 5 + 3)};
    alpha[i] = static_cast<png_byte>(i * 53);
  }
  png_color_16 transparent{};
  transparent.gray = static_cast<png_uint_16>(s.bit_depth < 8 ? 1 : 5);
  transparent.red = 5;
  transparent.green = 10;
  transparent.blue = 15;

  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, s.width, s.height, s.bit_depth, s.color_type,
               s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (s.color_type == PNG_COLOR_TYPE_PALETTE) {
    png_set_PLTE(png, info, palette.data(), entries);
    // Fewer tRNS entries than palette entries: the rest must read as opaque.
    if (s.trns) png_set_tRNS(png, info, alpha.data(), std::max(1, entries / 2), nullptr);
  } else if (s.trns) {
    png_set_tRNS(png, info, nullptr, 0, &transparent);
  }
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(file) == 0;
}

std::vector<RawPng> every_png_layout() {
  std::vector<RawPng> layouts;
  for (int depth : {1, 2, 4, 8, 16}) {
    for (bool trns : {false, true}) {
      layouts.push_back({PNG_COLOR_TYPE_GRAY, depth, trns});
      if (depth <= 8) layouts.push_back({PNG_COLOR_TYPE_PALETTE, depth, trns});
      if (depth >= 8) layouts.push_back({PNG_COLOR_TYPE_RGB, depth, trns});
      if (depth >= 8 && !trns) {
        layouts.push_back({PNG_COLOR_TYPE_GRAY_ALPHA, depth});
        layouts.push_back({PNG_COLOR_TYPE_RGBA, depth});
      }
    }
  }
  layouts.push_back({PNG_COLOR_TYPE_RGBA, 16, false, true});
  layouts.push_back({PNG_COLOR_TYPE_PALETTE, 4, true, true});
  layouts.push_back({PNG_COLOR_TYPE_GRAY, 2, false, true});
  return layouts;
}

Result<Image> read_through_oiio_module(const fs::path& path) {
  Result<const image_io::OiioModule*> module =
      image_io::load_oiio_module(path.string() + ": cannot read image");
  if (!module) return module.error();
  return (*module)->read(path.string());
}

void expect_same_image(const Image& ours, const Image& oiio, const std::string& what) {
  ASSERT_EQ(ours.width, oiio.width) << what;
  ASSERT_EQ(ours.height, oiio.height) << what;
  ASSERT_EQ(ours.channels, oiio.channels) << what;
  // Bit-identical floats, not merely close: golden comparisons must not move at all.
  ASSERT_EQ(ours.pixels, oiio.pixels) << what;
}

bool maps_contain(const std::string& needle) {
  std::ifstream maps("/proc/self/maps");
  const std::string text((std::istreambuf_iterator<char>(maps)), std::istreambuf_iterator<char>());
  return text.find(needle) != std::string::npos;
}

void write_bytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

std::string read_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void expect_read_error_names_path(const fs::path& path) {
  Result<Image> image = read_image(path.string());
  ASSERT_FALSE(image.ok()) << path;
  const std::string& message = image.error().message;
  EXPECT_EQ(message.rfind(path.string() + ": cannot read image: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "errors are one line: " << message;
}

TEST(PngIoTest, RoundTripEveryChannelCountWithinHalfStep) {
  for (int channels = 1; channels <= 4; ++channels) {
    SCOPED_TRACE("channels " + std::to_string(channels));
    const fs::path path = test::scratch_dir() / "round_trip.png";
    Image original = test::gradient_image(11, 5, channels);
    original.pixels[0] = NAN;    // the GL writes NaN to RGBA8 as 0
    original.pixels[1] = -0.5f;  // clamped to 0
    original.pixels[2] = 7.0f;   // clamped to 1
    ASSERT_TRUE(write_image(path.string(), original).ok());
    Result<Image> back = read_image(path.string());
    ASSERT_TRUE(back.ok()) << back.error().message;
    ASSERT_EQ(back->width, 11);
    ASSERT_EQ(back->height, 5);
    ASSERT_EQ(back->channels, channels);
    EXPECT_EQ(back->pixels[0], 0.0f);
    EXPECT_EQ(back->pixels[1], 0.0f);
    EXPECT_EQ(back->pixels[2], 1.0f);
    for (size_t i = 3; i < original.pixels.size(); ++i) {
      EXPECT_NEAR(back->pixels[i], original.pixels[i], 0.5 / 255.0 + 1e-6) << "index " << i;
    }
  }
}

TEST(PngIoTest, WriteRefusesMoreThanFourChannelsAndSaysWhatToDo) {
  const fs::path dir = test::scratch_dir();
  Status s = write_image((dir / "five.png").string(), test::constant_image(2, 2, 5, 0.5f));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.error().message.find((dir / "five.png").string() + ": cannot write image: "), std::string::npos)
      << s.error().message;
  EXPECT_NE(s.error().message.find(".exr"), std::string::npos) << s.error().message;
  EXPECT_TRUE(fs::is_empty(dir)) << "no temp file may remain";
}

TEST(PngIoTest, EveryPngLayoutReadsExactlyAsTheOiioModuleReadsIt) {
  const fs::path dir = test::scratch_dir();
  for (const RawPng& layout : every_png_layout()) {
    const std::string name = describe(layout);
    const fs::path path = dir / (name + ".png");
    ASSERT_TRUE(write_raw_png(path, layout)) << name;
    Result<Image> ours = read_image(path.string());
    ASSERT_TRUE(ours.ok()) << ours.error().message;
    Result<Image> oiio = read_through_oiio_module(path);
    ASSERT_TRUE(oiio.ok()) << oiio.error().message;
    expect_same_image(*ours, *oiio, name);
    // Channel count after expansion: palette -> RGB, tRNS adds alpha.
    const int base = layout.color_type == PNG_COLOR_TYPE_PALETTE ? 3 : file_channels(layout.color_type);
    EXPECT_EQ(ours->channels, base + (layout.trns ? 1 : 0)) << name;
  }
}

TEST(PngIoTest, SixteenBitSamplesKeepFullPrecision) {
  const fs::path path = test::scratch_dir() / "gray16.png";
  const RawPng layout{PNG_COLOR_TYPE_GRAY, 16};
  ASSERT_TRUE(write_raw_png(path, layout));
  Result<Image> image = read_image(path.string());
  ASSERT_TRUE(image.ok()) << image.error().message;
  const std::vector<png_byte> bytes = sample_bytes(layout);
  const unsigned first = (bytes[0] << 8) | bytes[1];  // big-endian in the file
  ASSERT_NE(first % 257, 0u) << "the first sample must not be an 8-bit value widened (v*257)";
  // Multiplying by the reciprocal, as OIIO does, so both readers agree to the bit.
  EXPECT_EQ(image->pixels[0], static_cast<float>(first) * (1.0f / 65535.0f));
}

TEST(PngIoTest, CommittedImagesReadExactlyAsTheOiioModuleReadsThem) {
  // Goldens and textures were written by OIIO; they are the files that matter most.
  int files = 0;
  for (const char* dir : {"golden_images", "textures"}) {
    for (const auto& entry : fs::directory_iterator(fs::path(PS_SOURCE_DIR) / dir)) {
      if (entry.path().extension() != ".png") continue;
      Result<Image> ours = read_image(entry.path().string());
      ASSERT_TRUE(ours.ok()) << ours.error().message;
      Result<Image> oiio = read_through_oiio_module(entry.path());
      ASSERT_TRUE(oiio.ok()) << oiio.error().message;
      expect_same_image(*ours, *oiio, entry.path().string());
      ++files;
    }
  }
  EXPECT_GT(files, 0);
}

TEST(PngIoTest, TruncatedPngGivesOneLineErrorNamingThePath) {
  const fs::path dir = test::scratch_dir();
  ASSERT_TRUE(write_image((dir / "whole.png").string(), test::gradient_image(64, 64, 4)).ok());
  const std::string whole = read_bytes(dir / "whole.png");
  // Just the signature, inside IHDR, inside IDAT, just before IEND.
  for (size_t keep : {size_t{8}, size_t{20}, whole.size() / 2, whole.size() - 13}) {
    const fs::path path = dir / ("cut_" + std::to_string(keep) + ".png");
    write_bytes(path, whole.substr(0, keep));
    expect_read_error_names_path(path);
  }
}

TEST(PngIoTest, CorruptImageDataGivesOneLineErrorNamingThePath) {
  const fs::path dir = test::scratch_dir();
  ASSERT_TRUE(write_image((dir / "whole.png").string(), test::gradient_image(64, 64, 4)).ok());
  std::string bytes = read_bytes(dir / "whole.png");
  for (size_t i = bytes.size() / 2; i < bytes.size() / 2 + 16; ++i) bytes[i] = static_cast<char>(~bytes[i]);
  const fs::path path = dir / "corrupt.png";
  write_bytes(path, bytes);
  expect_read_error_names_path(path);
}

TEST(PngIoTest, GarbageNamedPngGivesOneLineErrorNamingThePath) {
  const fs::path path = test::scratch_dir() / "garbage.png";
  write_bytes(path, "this is not an image at all, just text pretending to be one\n");
  expect_read_error_names_path(path);
}

TEST(PngIoTest, OversizedPngIsRefusedFromTheHeader) {
  const fs::path path = test::scratch_dir() / "wide.png";
  ASSERT_TRUE(write_raw_png(path, {PNG_COLOR_TYPE_GRAY, 8, false, false, 20000, 1}));
  Result<Image> image = read_image(path.string());
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.error().message.find(path.string() + ": image size 20000x1 is outside 1..16384"),
            std::string::npos)
      << image.error().message;
}

TEST(PngIoTest, ExrRoundTripGoesThroughTheOiioModule) {
  const fs::path path = test::scratch_dir() / "values.exr";
  Image image = test::gradient_image(5, 3, 2);
  image.pixels[0] = 1e-7f;
  image.pixels[1] = 123456.789f;  // beyond half float: the file must be 32-bit
  ASSERT_TRUE(write_image(path.string(), image).ok());
  Result<Image> back = read_image(path.string());
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->channels, 2);
  EXPECT_EQ(back->pixels, image.pixels);
  EXPECT_TRUE(maps_contain("libps_image_oiio"));
}

// ctest runs each test in its own process, so here the threads race to load the module first.
TEST(PngIoTest, ConcurrentFirstUseOfTheModuleWorksOnEveryThread) {
  const fs::path dir = test::scratch_dir();
  std::vector<std::thread> threads;
  std::vector<int> ok(4, 0);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      const std::string path = (dir / ("thread" + std::to_string(t) + ".exr")).string();
      const Image image = test::constant_image(4, 4, 3, 0.25f * t);
      Status written = write_image(path, image);
      Result<Image> back = read_image(path);
      ok[t] = written.ok() && back.ok() && back->pixels == image.pixels;
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(ok, std::vector<int>(4, 1));
}

}  // namespace
}  // namespace ps
