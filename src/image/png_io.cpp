// PNG through libpng directly, so the common case (every render, golden image and albedo texture)
// never loads OpenImageIO and the ~270 libraries behind it.
//
// libpng reports errors by longjmp from inside its own calls. Every libpng call therefore runs in
// a "step" (a plain function on plain data) started by run_png_step, which holds the setjmp;
// everything with a destructor (vectors, strings, the Image) lives in the callers, outside the
// frames a longjmp skips.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <png.h>

#include "image/image_io_internal.h"

namespace ps::image_io {
namespace {

// Everything the libpng callbacks touch: plain data only, because png_longjmp skips destructors.
struct PngContext {
  std::FILE* file = nullptr;
  char message[256] = {};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* ctx = static_cast<PngContext*>(png_get_error_ptr(png));
  std::snprintf(ctx->message, sizeof ctx->message, "%s", message);
  png_longjmp(png, 1);
}

// Warnings are about ancillary chunks (bad sRGB profile, text encoding) that never change the
// pixels we return; libpng's default would print them to stderr and break the one-line-per-error
// promise of the CLI.
void on_png_warning(png_structp, png_const_charp) {}

void read_from_file(png_structp png, png_bytep data, size_t length) {
  auto* ctx = static_cast<PngContext*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, ctx->file) != length) {
    png_error(png, std::ferror(ctx->file) ? std::strerror(errno) : "unexpected end of file (truncated?)");
  }
}

void write_to_file(png_structp png, png_bytep data, size_t length) {
  auto* ctx = static_cast<PngContext*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, length, ctx->file) != length) png_error(png, std::strerror(errno));
}

void flush_file(png_structp png) {
  auto* ctx = static_cast<PngContext*>(png_get_io_ptr(png));
  if (std::fflush(ctx->file) != 0) png_error(png, std::strerror(errno));
}

// The only function holding a setjmp. `step` must not own anything with a destructor.
bool run_png_step(png_structp png, void (*step)(png_structp, void*), void* args) {
  if (setjmp(png_jmpbuf(png))) return false;
  step(png, args);
  return true;
}

// Owns the libpng structs and the FILE for one read or write; destroys them however we leave.
class PngFile {
 public:
  PngFile(const std::string& path, bool for_writing) : writing_(for_writing) {
    ctx_.file = std::fopen(path.c_str(), for_writing ? "wb" : "rb");
    if (!ctx_.file) {
      std::snprintf(ctx_.message, sizeof ctx_.message, "%s", std::strerror(errno));
      return;
    }
    png_ = for_writing ? png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx_, on_png_error, on_png_warning)
                       : png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx_, on_png_error, on_png_warning);
    if (png_) info_ = png_create_info_struct(png_);
    if (!png_ || !info_) {
      std::snprintf(ctx_.message, sizeof ctx_.message, "out of memory creating the libpng reader/writer");
      return;
    }
    if (for_writing) {
      png_set_write_fn(png_, &ctx_, write_to_file, flush_file);
    } else {
      png_set_read_fn(png_, &ctx_, read_from_file);
    }
  }
  ~PngFile() {
    if (writing_) {
      png_destroy_write_struct(&png_, &info_);
    } else {
      png_destroy_read_struct(&png_, &info_, nullptr);
    }
    if (ctx_.file) std::fclose(ctx_.file);
  }
  PngFile(const PngFile&) = delete;
  PngFile& operator=(const PngFile&) = delete;

  bool ready() const { return info_ != nullptr; }
  png_structp png() const { return png_; }
  png_infop info() const { return info_; }
  const char* message() const { return ctx_.message; }
  // Closes the file now so a failing close (disk full, quota) is reported, not lost.
  bool close() {
    std::FILE* file = ctx_.file;
    ctx_.file = nullptr;
    if (!file || std::fclose(file) == 0) return true;
    std::snprintf(ctx_.message, sizeof ctx_.message, "%s", std::strerror(errno));
    return false;
  }

 private:
  bool writing_;
  PngContext ctx_;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
};

// ---- reading ----

// One struct for all read steps: plain data, filled in as the steps go.
struct ReadArgs {
  png_infop info = nullptr;
  png_uint_32 width = 0, height = 0;
  int channels = 0;    // after expansion: gray 1, gray+alpha 2, RGB 3, RGBA 4
  int bit_depth = 0;   // after expansion: 8 or 16
  bool interlaced = false;
  size_t row_bytes = 0;
  png_bytep raw = nullptr;     // one row, or the whole image when interlaced
  png_bytep* rows = nullptr;   // row pointers into `raw` (interlaced only)
  float* out = nullptr;        // width * height * channels
};

// Reads up to the image data and predicts the channel count after expansion, so the caller can
// refuse absurd sizes before libpng or we allocate anything for the pixels.
void read_header_step(png_structp png, void* p) {
  auto* a = static_cast<ReadArgs*>(p);
  png_read_info(png, a->info);
  a->width = png_get_image_width(png, a->info);
  a->height = png_get_image_height(png, a->info);
  const int color_type = png_get_color_type(png, a->info);
  const bool trns = png_get_valid(png, a->info, PNG_INFO_tRNS) != 0;
  a->channels = (color_type & PNG_COLOR_MASK_PALETTE) ? 3 : png_get_channels(png, a->info);
  if (trns && !(color_type & PNG_COLOR_MASK_ALPHA)) a->channels += 1;
}

// Same expansion as OpenImageIO's PNG reader, so the files read exactly as they did through it:
// palette -> RGB, tRNS -> alpha, 1/2/4-bit gray -> 8 bit; 16 bit stays 16 bit; no gamma change.
void read_expand_step(png_structp png, void* p) {
  auto* a = static_cast<ReadArgs*>(p);
  const int color_type = png_get_color_type(png, a->info);
  const int bit_depth = png_get_bit_depth(png, a->info);
  if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
  if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) png_set_expand_gray_1_2_4_to_8(png);
  if (png_get_valid(png, a->info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(png);
  a->interlaced = png_set_interlace_handling(png) > 1;
  png_read_update_info(png, a->info);
  a->channels = png_get_channels(png, a->info);
  a->bit_depth = png_get_bit_depth(png, a->info);
  a->row_bytes = png_get_rowbytes(png, a->info);
}

// 8 bit -> [0,1] and 16 bit (big-endian in the file) -> [0,1], multiplying by the reciprocal as
// OpenImageIO does (v/255 would differ from it in the last bit for half the values).
void convert_row(const ReadArgs& a, const png_byte* raw, float* out) {
  const size_t n = static_cast<size_t>(a.width) * a.channels;
  if (a.bit_depth == 16) {
    constexpr float kScale = 1.0f / 65535.0f;
    for (size_t i = 0; i < n; ++i) out[i] = static_cast<float>((raw[2 * i] << 8) | raw[2 * i + 1]) * kScale;
  } else {
    constexpr float kScale = 1.0f / 255.0f;
    for (size_t i = 0; i < n; ++i) out[i] = static_cast<float>(raw[i]) * kScale;
  }
}

void read_rows_step(png_structp png, void* p) {
  auto* a = static_cast<ReadArgs*>(p);
  const size_t floats_per_row = static_cast<size_t>(a->width) * a->channels;
  if (a->interlaced) {
    png_read_image(png, a->rows);
    for (png_uint_32 y = 0; y < a->height; ++y) convert_row(*a, a->rows[y], a->out + y * floats_per_row);
  } else {
    // Row by row: only one row of file samples is ever held next to the float image.
    for (png_uint_32 y = 0; y < a->height; ++y) {
      png_read_row(png, a->raw, nullptr);
      convert_row(*a, a->raw, a->out + y * floats_per_row);
    }
  }
  // The trailing chunks (text, time) are not read: nothing in them changes the pixels.
}

// ---- writing ----

struct WriteArgs {
  png_infop info = nullptr;
  const Image* image = nullptr;
  png_bytep row = nullptr;  // width * channels bytes
};

// PNG stores 8 bit: clamp to [0,1] and round to nearest (v*255+0.5), so a round trip is within
// 0.5/255. NaN becomes 0, matching what the GL does when it writes NaN to RGBA8.
void quantize_8bit(const float* pixels, size_t count, std::uint8_t* bytes) {
  for (size_t i = 0; i < count; ++i) {
    float v = std::isnan(pixels[i]) ? 0.0f : std::clamp(pixels[i], 0.0f, 1.0f);
    bytes[i] = static_cast<std::uint8_t>(v * 255.0f + 0.5f);
  }
}

void write_step(png_structp png, void* p) {
  auto* a = static_cast<WriteArgs*>(p);
  const Image& image = *a->image;
  static constexpr int kColorType[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                       PNG_COLOR_TYPE_RGBA};
  png_set_IHDR(png, a->info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height), 8,
               kColorType[image.channels - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, a->info);
  const size_t floats_per_row = static_cast<size_t>(image.width) * image.channels;
  for (int y = 0; y < image.height; ++y) {
    quantize_8bit(image.pixels.data() + y * floats_per_row, floats_per_row, a->row);
    png_write_row(png, a->row);
  }
  png_write_end(png, nullptr);
}

}  // namespace

Result<bool> has_png_signature(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return make_error(path + ": cannot read image: " + std::strerror(errno));
  png_byte signature[8] = {};
  const size_t got = std::fread(signature, 1, sizeof signature, file);
  const bool failed = std::ferror(file) != 0;
  const int read_errno = errno;
  std::fclose(file);
  if (failed) return make_error(path + ": cannot read image: " + std::strerror(read_errno));
  return got == sizeof signature && png_sig_cmp(signature, 0, sizeof signature) == 0;
}

Result<Image> read_png(const std::string& path) {
  auto fail = [&](const char* what) { return make_error(path + ": cannot read image: " + what); };
  PngFile file(path, /*for_writing=*/false);
  if (!file.ready()) return fail(file.message());
  ReadArgs args;
  args.info = file.info();
  if (!run_png_step(file.png(), read_header_step, &args)) return fail(file.message());
  // Checked before libpng allocates its row buffers or we allocate the image.
  // libpng caps both sides at 2^31-1 (and by default at 10^6), so they fit an int.
  const int width = static_cast<int>(args.width);
  const int height = static_cast<int>(args.height);
  if (Status shape = check_shape(path, width, height, args.channels); !shape) return shape.error();
  if (!run_png_step(file.png(), read_expand_step, &args)) return fail(file.message());

  Image image;
  image.width = width;
  image.height = height;
  image.channels = args.channels;
  image.file_bits = args.bit_depth == 8 ? 8 : 0;  // after expansion: 8 or 16
  image.pixels.resize(static_cast<size_t>(width) * height * args.channels);
  std::vector<png_byte> raw(args.row_bytes * (args.interlaced ? args.height : 1));
  std::vector<png_bytep> rows;
  if (args.interlaced) {
    for (png_uint_32 y = 0; y < args.height; ++y) rows.push_back(raw.data() + y * args.row_bytes);
  }
  args.raw = raw.data();
  args.rows = rows.data();
  args.out = image.pixels.data();
  if (!run_png_step(file.png(), read_rows_step, &args)) return fail(file.message());
  return image;
}

Status write_png(const std::string& file_path, const std::string& target, const Image& image) {
  auto fail = [&](const std::string& what) { return make_error(target + ": cannot write image: " + what); };
  if (image.channels > 4) {
    return fail("PNG holds 1 to 4 channels (gray, gray+alpha, RGB, RGBA), not " +
                std::to_string(image.channels) + "; write .exr to keep them all");
  }
  PngFile file(file_path, /*for_writing=*/true);
  if (!file.ready()) return fail(file.message());
  std::vector<png_byte> row(static_cast<size_t>(image.width) * image.channels);
  WriteArgs args{file.info(), &image, row.data()};
  if (!run_png_step(file.png(), write_step, &args)) return fail(file.message());
  if (!file.close()) return fail(file.message());
  return ok_status();
}

}  // namespace ps::image_io
