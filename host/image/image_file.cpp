#include "image_file.h"

#include "file_extension.h"
#include "input_file.h"
#include "jpeg_file.h"
#include "png_file.h"
#include "srgb.h"

#include <cctype>
#include <cstdio>
#include <cstring>
#include <vector>

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
  const std::string ext = fileExtension(path);
  const bool png = isPng(b, n), jpeg = isJpeg(b, n);
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
  if (wantPng ? png : jpeg) return true;
  if (wantPng ? jpeg : png) {
    *error = "'" + path + "' is a " + (png ? "PNG" : "JPEG") + " image named ." + ext + ": name it ." +
             (png ? "png" : "jpg");
    return false;
  }
  *error = "cannot decode image '" + path + "': not a " + (wantPng ? "PNG" : "JPEG") + " file" +
           (n == 0 ? " (the file is empty)" : "");
  return false;
}

// The header of an opened file whose format checkFormat found, read from its start.
bool readHeader(FILE* file, const std::string& path, ImageHeader* header, std::string* error) {
  if (header->format == ImageFormat::Png)
    return fseek(file, 8, SEEK_SET) == 0 &&
           readPngHeader(file, path, &header->width, &header->height, &header->depth, error);
  std::string message = "cannot seek";
  header->depth = 8;
  if (fseek(file, 0, SEEK_SET) == 0 && decodeJpeg(file, &header->width, &header->height, nullptr, &message))
    return true;
  *error = "cannot decode image '" + path + "': " + message;
  return false;
}

// Opens the file and checks its format and header; the file is left after what was read.
FILE* openAndProbe(const std::string& path, ImageHeader* header, std::string* error) {
  FILE* file = openImageFile(path, error);
  if (!file) return nullptr;
  uint8_t head[16];
  size_t n = fread(head, 1, sizeof(head), file);
  bool ok = checkFormat(path, head, n, &header->format, error) && readHeader(file, path, header, error);
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

// The file at `path` opened again, decoded at `depth` bits into `out` (decodePng, decodeJpeg).
void decodeAt(const std::string& path, const ImageHeader& header, int depth, void* out) {
  ImageHeader now;
  std::string error;
  FileCloser file{openAndProbe(path, &now, &error)};
  if (!file.file) throw ImageInputError(error);
  if (now.width != header.width || now.height != header.height || now.format != header.format)
    throw ImageInputError("cannot decode image '" + path + "': the file changed while it was read");
  std::string message;
  bool ok = fseek(file.file, 0, SEEK_SET) == 0 &&
            (header.format == ImageFormat::Png
                 ? decodePng(file.file, header.width, header.height, depth, out, &message)
                 : decodeJpeg(file.file, &now.width, &now.height, static_cast<uint8_t*>(out), &message));
  if (!ok) throw ImageInputError("cannot decode image '" + path + "': " + message);
}

// Refuses an image whose linear RGB floats would take more than maxBytes.
void checkBudget(const std::string& path, int width, int height, uint64_t maxBytes) {
  const uint64_t bytes = uint64_t(width) * uint64_t(height) * 3 * sizeof(float);
  if (bytes <= maxBytes) return;
  char sizes[96];
  snprintf(sizes, sizeof sizes, "%.1f MiB, more than the %.1f MiB allowed", double(bytes) / (1 << 20),
           double(maxBytes) / (1 << 20));
  throw ImageInputError("image '" + path + "' is " + std::to_string(width) + "x" + std::to_string(height) +
                        ": its linear floats would take " + sizes);
}

// 8-bit sRGB decoded to linear, alpha dropped.
LinearImage linearFromRgba8(const ImageRGBA8& rgba) {
  const float* decode = srgbDecodeTable();
  LinearImage out{FloatImage{rgba.width, rgba.height, 3, std::vector<float>(size_t(rgba.width) * rgba.height * 3)}, true};
  for (size_t i = 0; i < size_t(rgba.width) * size_t(rgba.height); ++i)
    for (size_t c = 0; c < 3; ++c) out.image.pixels[i * 3 + c] = decode[rgba.pixels[i * 4 + c]];
  return out;
}

// A 16-bit PNG at its full precision: sRGB decoded to linear, alpha dropped.
LinearImage readSixteenBit(const std::string& path, const ImageHeader& header) {
  std::vector<uint16_t> rgb16(size_t(header.width) * size_t(header.height) * 3);
  decodeAt(path, header, 16, rgb16.data());
  std::vector<float> decode(65536);
  for (size_t i = 0; i < decode.size(); ++i) decode[i] = float(srgbToLinear(double(i) / 65535.0));
  LinearImage out{FloatImage{header.width, header.height, 3, std::vector<float>(rgb16.size())}, true};
  for (size_t i = 0; i < rgb16.size(); ++i) out.image.pixels[i] = decode[rgb16[i]];
  return out;
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
  decodeAt(path, header, 8, rgba);
}

ImageRGBA8 loadImage(const std::string& path) {
  const ImageHeader header = probeImage(path);
  ImageRGBA8 image{header.width, header.height, std::vector<uint8_t>(size_t(header.width) * header.height * 4)};
  decodeImage(path, header, image.pixels.data());
  return image;
}

LinearImage readSrgbImage(const std::string& path, uint64_t maxBytes) {
  const ImageHeader header = probeImage(path);
  checkBudget(path, header.width, header.height, maxBytes);
  if (header.format == ImageFormat::Png && header.depth == 16) return readSixteenBit(path, header);
  ImageRGBA8 rgba{header.width, header.height, std::vector<uint8_t>(size_t(header.width) * header.height * 4)};
  decodeImage(path, header, rgba.pixels.data());
  return linearFromRgba8(rgba);
}
