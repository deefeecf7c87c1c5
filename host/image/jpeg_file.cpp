#include "jpeg_file.h"

#include <csetjmp>

#include <jpeglib.h>

namespace {

// libjpeg reports through this manager: errors, and warnings too, end the decode by a longjmp
// with the message; nothing is printed.
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

void readScanlines(jpeg_decompress_struct& info, uint8_t* rgba) {
  info.out_color_space = JCS_EXT_RGBA;
  jpeg_start_decompress(&info);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = rgba + size_t(info.output_scanline) * info.output_width * 4;
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
}

}  // namespace

bool isJpeg(const uint8_t* bytes, size_t n) { return n >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff; }

// C-style: between setjmp and longjmp only libjpeg's objects live.
bool decodeJpeg(FILE* file, int* width, int* height, uint8_t* rgba, std::string* message) {
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
  const bool sizeMatches = !rgba || (int(info.image_width) == *width && int(info.image_height) == *height);
  if (!colour || !sizeMatches) {
    *message = !colour ? "CMYK and YCCK JPEGs are not supported" : "the file changed while it was read";
    jpeg_destroy_decompress(&info);
    return false;
  }
  *width = int(info.image_width);
  *height = int(info.image_height);
  if (rgba) readScanlines(info, rgba);
  jpeg_destroy_decompress(&info);
  return true;
}
