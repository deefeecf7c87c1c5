#include "image_load.h"

#include "input_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <jpeglib.h>
#include <png.h>

namespace {

// Opens an image for reading: a regular file only (input_file.h).
FILE* openImageFile(const std::string& path, std::string* error) {
  std::string why;
  FILE* file = openRegularStream(path, &why);
  if (!file) *error = "cannot open image '" + path + "': " + why;
  return file;
}

struct FileCloser {
  FILE* file;
  ~FileCloser() {
    if (file) fclose(file);
  }
};

std::string lowerExtension(const std::string& path) {
  size_t slash = path.find_last_of('/');
  size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

const uint8_t kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

bool startsWith(const uint8_t* bytes, size_t n, const char* prefix, size_t length) {
  return n >= length && memcmp(bytes, prefix, length) == 0;
}

// The name of an image format other than PNG and JPEG recognised by its signature, or null.
const char* foreignFormat(const uint8_t* b, size_t n) {
  if (startsWith(b, n, "GIF87a", 6) || startsWith(b, n, "GIF89a", 6)) return "GIF";
  if (startsWith(b, n, "BM", 2)) return "BMP";
  if (n >= 3 && b[0] == 'P' && b[1] >= '1' && b[1] <= '7' && std::isspace(b[2])) {
    static const char* const names[] = {"PBM", "PGM", "PPM", "PBM", "PGM", "PPM", "PAM"};
    return names[b[1] - '1'];
  }
  if (startsWith(b, n, "RIFF", 4) && n >= 12 && memcmp(b + 8, "WEBP", 4) == 0) return "WebP";
  if (startsWith(b, n, "II*\0", 4) || startsWith(b, n, "MM\0*", 4)) return "TIFF";
  if (startsWith(b, n, "8BPS", 4)) return "PSD";
  if (startsWith(b, n, "#?RADIANCE", 10) || startsWith(b, n, "#?RGBE", 6)) return "Radiance HDR";
  if (startsWith(b, n, "qoif", 4)) return "QOI";
  return nullptr;
}

// The format the extension names, checked against the first bytes of the file.
bool checkFormat(const std::string& path, const uint8_t* b, size_t n, ImageFormat* format, std::string* error) {
  const std::string ext = lowerExtension(path);
  const bool isPng = n >= 8 && memcmp(b, kPngSignature, 8) == 0;
  const bool isJpeg = n >= 3 && b[0] == 0xff && b[1] == 0xd8 && b[2] == 0xff;
  const char* foreign = foreignFormat(b, n);
  if (foreign) {
    *error = "'" + path + "' is a " + foreign + " image: raytex reads PNG and JPEG";
    return false;
  }
  if (ext != "png" && ext != "jpg" && ext != "jpeg") {
    *error = "'" + path + "' is not named .png, .jpg or .jpeg: raytex reads PNG and JPEG";
    return false;
  }
  *format = ext == "png" ? ImageFormat::Png : ImageFormat::Jpeg;
  const bool wantPng = *format == ImageFormat::Png;
  if (wantPng ? isPng : isJpeg) return true;
  if (wantPng ? isJpeg : isPng) {
    *error = "'" + path + "' is a " + (isPng ? "PNG" : "JPEG") + " image named ." + ext + ": name it ." +
             (isPng ? "png" : "jpg");
    return false;
  }
  *error = "cannot decode image '" + path + "': not a " + (wantPng ? "PNG" : "JPEG") + " file" +
           (n == 0 ? " (the file is empty)" : "");
  return false;
}

uint32_t bigEndian32(const uint8_t* b) {
  return uint32_t(b[0]) << 24 | uint32_t(b[1]) << 16 | uint32_t(b[2]) << 8 | uint32_t(b[3]);
}

// PNG: the IHDR chunk, which the PNG specification puts first.
bool probePng(FILE* file, const std::string& path, ImageHeader* header, std::string* error) {
  uint8_t ihdr[25];
  if (fread(ihdr, 1, sizeof(ihdr), file) != sizeof(ihdr) || bigEndian32(ihdr) != 13 ||
      memcmp(ihdr + 4, "IHDR", 4) != 0) {
    *error = "cannot decode image '" + path + "': the PNG header (IHDR) is missing or malformed";
    return false;
  }
  uint32_t w = bigEndian32(ihdr + 8), h = bigEndian32(ihdr + 12);
  if (w == 0 || h == 0 || w > 0x7fffffffu || h > 0x7fffffffu) {
    *error = "cannot decode image '" + path + "': the PNG header gives a size of " + std::to_string(w) + "x" +
             std::to_string(h);
    return false;
  }
  header->width = int(w);
  header->height = int(h);
  return true;
}

// libjpeg reports through this manager: errors, and warnings too (a truncated file is only a
// warning to libjpeg), end the decode by a longjmp with the message; nothing is printed.
struct JpegErrors {
  jpeg_error_mgr manager;
  jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void jpegFail(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  info->err->format_message(info, errors->message);
  longjmp(errors->jump, 1);
}

void jpegMessage(j_common_ptr info, int level) {
  if (level < 0) jpegFail(info);  // a warning: corrupt or truncated data
}

void jpegQuiet(j_common_ptr) {}

// Reads the JPEG header (markers up to the scan), and when rgba is given decodes into it.
// C-style: between setjmp and longjmp only libjpeg's objects live.
bool runJpeg(FILE* file, ImageHeader* header, uint8_t* rgba, std::string* message) {
  jpeg_decompress_struct info;
  JpegErrors errors;
  info.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = jpegFail;
  errors.manager.emit_message = jpegMessage;
  errors.manager.output_message = jpegQuiet;
  errors.message[0] = '\0';
  if (setjmp(errors.jump)) {
    jpeg_destroy_decompress(&info);
    *message = errors.message;
    return false;
  }
  jpeg_create_decompress(&info);
  jpeg_stdio_src(&info, file);
  jpeg_read_header(&info, TRUE);
  const bool colour = info.jpeg_color_space == JCS_GRAYSCALE || info.jpeg_color_space == JCS_YCbCr ||
                      info.jpeg_color_space == JCS_RGB;
  const bool sizeMatches = !rgba || (int(info.image_width) == header->width && int(info.image_height) == header->height);
  if (!colour || !sizeMatches) {
    *message = !colour ? "CMYK and YCCK JPEGs are not supported" : "the file changed while it was read";
    jpeg_destroy_decompress(&info);
    return false;
  }
  header->width = int(info.image_width);
  header->height = int(info.image_height);
  if (rgba) {
    info.out_color_space = JCS_EXT_RGBA;
    jpeg_start_decompress(&info);
    while (info.output_scanline < info.output_height) {
      JSAMPROW row = rgba + size_t(info.output_scanline) * info.output_width * 4;
      jpeg_read_scanlines(&info, &row, 1);
    }
    jpeg_finish_decompress(&info);
  }
  jpeg_destroy_decompress(&info);
  return true;
}

// libpng: errors end the decode by a longjmp with the message; warnings (about ancillary
// chunks, which raytex does not use) are dropped; nothing is printed.
struct PngErrors {
  char message[256];
};

[[noreturn]] void pngFail(png_structp png, png_const_charp message) {
  auto* errors = static_cast<PngErrors*>(png_get_error_ptr(png));
  snprintf(errors->message, sizeof(errors->message), "%s", message);
  png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}

void pngRead(png_structp png, png_bytep data, size_t length) {
  if (fread(data, 1, length, static_cast<FILE*>(png_get_io_ptr(png))) != length) png_error(png, "the file ends early");
}

// The transforms that turn any non-palette PNG into 8-bit RGBA as stored (no gamma applied;
// 16-bit channels keep their high byte).
void setRgbaTransforms(png_structp png, png_infop info) {
  png_byte colorType = png_get_color_type(png, info);
  png_set_expand(png);
  png_set_strip_16(png);
  png_set_gray_to_rgb(png);
  if (!(colorType & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS))
    png_set_add_alpha(png, 0xff, PNG_FILLER_AFTER);
}

// Palette PNGs are read as one index per byte at the start of each RGBA row, checked against
// the palette's length (libpng itself maps an index past the palette to whatever memory
// follows it), then expanded from the end of the row backwards.
bool expandPalette(png_structp png, png_infop info, uint8_t* rgba, int width, int height, std::string* message) {
  png_colorp palette = nullptr;
  int paletteSize = 0;
  png_get_PLTE(png, info, &palette, &paletteSize);
  png_bytep alpha = nullptr;
  int alphaCount = 0;
  if (png_get_valid(png, info, PNG_INFO_tRNS)) png_get_tRNS(png, info, &alpha, &alphaCount, nullptr);
  for (int y = 0; y < height; ++y) {
    uint8_t* row = rgba + size_t(y) * width * 4;
    for (int x = 0; x < width; ++x)
      if (row[x] >= paletteSize) {
        *message = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") uses colour " +
                   std::to_string(row[x]) + " of a palette of " + std::to_string(paletteSize);
        return false;
      }
    for (int x = width - 1; x >= 0; --x) {
      const int index = row[x];
      uint8_t* p = row + size_t(x) * 4;
      p[3] = index < alphaCount ? alpha[index] : 255;
      p[2] = palette[index].blue;
      p[1] = palette[index].green;
      p[0] = palette[index].red;
    }
  }
  return true;
}

// Decodes into rgba (header's size); C-style: between setjmp and longjmp only libpng's objects
// and the row pointers (made before setjmp) live.
bool runPng(FILE* file, const ImageHeader& header, uint8_t* rgba, std::string* message) {
  PngErrors errors{};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, pngFail, pngWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<png_bytep> rows(size_t(header.height));
  for (size_t y = 0; y < rows.size(); ++y) rows[y] = rgba + y * size_t(header.width) * 4;
  if (!info) {
    png_destroy_read_struct(&png, nullptr, nullptr);
    *message = "out of memory";
    return false;
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_read_struct(&png, &info, nullptr);
    *message = errors.message;
    return false;
  }
  png_set_read_fn(png, file, pngRead);
  png_set_user_limits(png, kMaxImageFileSide, kMaxImageFileSide);
  png_read_info(png, info);
  if (int(png_get_image_width(png, info)) != header.width || int(png_get_image_height(png, info)) != header.height)
    png_error(png, "the file changed while it was read");
  const bool palette = png_get_color_type(png, info) == PNG_COLOR_TYPE_PALETTE;
  if (palette)
    png_set_packing(png);  // 1, 2 and 4-bit indices: one byte each
  else
    setRgbaTransforms(png, info);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  if (png_get_rowbytes(png, info) != size_t(header.width) * (palette ? 1 : 4))
    png_error(png, "unexpected row layout after conversion to RGBA");
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  bool ok = !palette || expandPalette(png, info, rgba, header.width, header.height, message);
  png_destroy_read_struct(&png, &info, nullptr);
  return ok;
}

// Opens the file and checks its format and header; the file is left after what was read.
FILE* openAndProbe(const std::string& path, ImageHeader* header, std::string* error) {
  FILE* file = openImageFile(path, error);
  if (!file) return nullptr;
  uint8_t head[16];
  size_t n = fread(head, 1, sizeof(head), file);
  bool ok = checkFormat(path, head, n, &header->format, error);
  if (ok && header->format == ImageFormat::Png) {
    ok = fseek(file, 8, SEEK_SET) == 0 && probePng(file, path, header, error);
  } else if (ok) {
    std::string message = "cannot seek";
    ok = fseek(file, 0, SEEK_SET) == 0 && runJpeg(file, header, nullptr, &message);
    if (!ok) *error = "cannot decode image '" + path + "': " + message;
  }
  if (ok && (header->width > kMaxImageFileSide || header->height > kMaxImageFileSide)) {
    *error = "image '" + path + "' is " + std::to_string(header->width) + "x" + std::to_string(header->height) +
             ": raytex reads images of at most " + std::to_string(kMaxImageFileSide) + " a side";
    ok = false;
  }
  if (!ok) {
    fclose(file);
    return nullptr;
  }
  return file;
}

}  // namespace

ImageHeader probeImage(const std::string& path) {
  ImageHeader header;
  std::string error;
  FILE* file = openAndProbe(path, &header, &error);
  if (!file) throw ImageInputError(error);
  fclose(file);
  return header;
}

void decodeImage(const std::string& path, const ImageHeader& header, uint8_t* rgba) {
  ImageHeader now;
  std::string error;
  FileCloser file{openAndProbe(path, &now, &error)};
  if (!file.file) throw ImageInputError(error);
  if (now.width != header.width || now.height != header.height || now.format != header.format)
    throw ImageInputError("cannot decode image '" + path + "': the file changed while it was read");
  std::string message;
  bool ok = fseek(file.file, 0, SEEK_SET) == 0 &&
            (header.format == ImageFormat::Png ? runPng(file.file, header, rgba, &message)
                                               : runJpeg(file.file, &now, rgba, &message));
  if (!ok) throw ImageInputError("cannot decode image '" + path + "': " + message);
}

ImageRGBA8 loadImage(const std::string& path) {
  const ImageHeader header = probeImage(path);
  ImageRGBA8 image{header.width, header.height, std::vector<uint8_t>(size_t(header.width) * header.height * 4)};
  decodeImage(path, header, image.pixels.data());
  return image;
}
