// Image files read before they are trusted (image_file.h, scene_images.h): only PNG and JPEG,
// named for what they hold; sizes from the header checked before any decoding; corrupt and
// truncated files refused; paths that are not regular files refused without blocking. The
// hostile files are those of the malformed corpus (tests/malformed/images/make_hostile.py).
#include "gpu_scene.h"
#include "image_file.h"
#include "png_file.h"
#include "parser.h"
#include "reference_render.h"
#include "scene_images.h"
#include "support/files.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <thread>

namespace fs = std::filesystem;

namespace {

const std::string kHostile = kSourceDir + "/tests/malformed/images/";

// The message of the ImageInputError that loading `path` throws.
std::string loadError(const std::string& path) {
  try {
    ImageRGBA8 image = loadImage(path);
    ADD_FAILURE() << path << " was decoded as " << image.width << "x" << image.height;
  } catch (const ImageInputError& e) {
    return e.what();
  }
  return "";
}


// A PNG with 8-bit samples, each row given without its filter byte.
std::string pngFile(int width, int height, int colorType, const std::string& pixels, const std::string& plte = "",
                    const std::string& trns = "") {
  auto be32 = [](uint32_t v) {
    return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
  };
  auto chunk = [&](const std::string& kind, const std::string& body) {
    std::string data = kind + body;
    uint32_t crc = uint32_t(crc32(0, reinterpret_cast<const Bytef*>(data.data()), uInt(data.size())));
    return be32(uint32_t(body.size())) + data + be32(crc);
  };
  std::string raw;
  size_t rowBytes = pixels.size() / size_t(height);
  for (int y = 0; y < height; ++y) raw += '\0' + pixels.substr(size_t(y) * rowBytes, rowBytes);
  uLongf size = compressBound(uLong(raw.size()));
  std::string packed(size, '\0');
  compress(reinterpret_cast<Bytef*>(packed.data()), &size, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
  packed.resize(size);
  std::string ihdr = be32(uint32_t(width)) + be32(uint32_t(height)) + std::string{8, char(colorType), 0, 0, 0};
  std::string out = "\x89PNG\r\n\x1a\n" + chunk("IHDR", ihdr);
  if (!plte.empty()) out += chunk("PLTE", plte);
  if (!trns.empty()) out += chunk("tRNS", trns);
  return out + chunk("IDAT", packed) + chunk("IEND", "");
}

TEST(ImageLoad, OtherFormatsAreRefusedByName) {
  EXPECT_NE(loadError(kHostile + "canvas-16384.gif").find("is a GIF image: raytex reads PNG and JPEG"), std::string::npos);
  EXPECT_NE(loadError(kHostile + "header-only.ppm").find("is a PPM image"), std::string::npos);
  EXPECT_NE(loadError(kHostile + "header-only.bmp").find("is a BMP image"), std::string::npos);
  EXPECT_NE(loadError(kHostile + "header-only.tga").find("is not named .png, .jpg or .jpeg"), std::string::npos);
  // The same GIF under a PNG name: the content decides, and it is named.
  fs::path dir = freshTempDir("image_load_formats");
  fs::copy_file(kHostile + "canvas-16384.gif", dir / "canvas.png");
  EXPECT_NE(loadError((dir / "canvas.png").string()).find("is a GIF image"), std::string::npos);
}

TEST(ImageLoad, ContentMustMatchTheExtension) {
  EXPECT_NE(loadError(kHostile + "tga-named.png").find("'" + kHostile + "tga-named.png': not a PNG file"),
            std::string::npos);
  EXPECT_NE(loadError(kHostile + "jpeg-named.png").find("is a JPEG image named .png"), std::string::npos);
  fs::path dir = freshTempDir("image_load_mismatch");
  fs::copy_file(kSourceDir + "/textures/uv_grid.png", dir / "grid.jpg");
  EXPECT_NE(loadError((dir / "grid.jpg").string()).find("is a PNG image named .jpg"), std::string::npos);
}

TEST(ImageLoad, ExtensionsInAnyCase) {
  fs::path dir = freshTempDir("image_load_case");
  fs::copy_file(kSourceDir + "/textures/uv_grid.png", dir / "GRID.PNG");
  fs::copy_file(kSourceDir + "/textures/earth.jpg", dir / "earth.JPEG");
  fs::copy_file(kSourceDir + "/textures/earth.jpg", dir / "earth.Jpg");
  for (const char* name : {"GRID.PNG", "earth.JPEG", "earth.Jpg"}) {
    ImageRGBA8 image;
    EXPECT_NO_THROW(image = loadImage((dir / name).string()));
    EXPECT_EQ(image.pixels.size(), size_t(image.width) * image.height * 4) << name;
  }
}

TEST(ImageLoad, ProbeReadsTheHeader) {
  ImageHeader h;
  ASSERT_NO_THROW(h = probeImage(kSourceDir + "/textures/earth.jpg"));
  EXPECT_EQ(h.width, 2048);
  EXPECT_EQ(h.height, 1024);
  EXPECT_EQ(h.format, ImageFormat::Jpeg);
  ASSERT_NO_THROW(h = probeImage(kSourceDir + "/textures/uv_grid.png"));
  EXPECT_EQ(h.width, 512);
  EXPECT_EQ(h.height, 256);
  EXPECT_EQ(h.format, ImageFormat::Png);
}

// A side over 16384 is refused from the header (the file is 96 bytes); 16384 is accepted.
TEST(ImageLoad, SideOver16384IsRefusedFromTheHeader) {
  ImageHeader h;
  try {
    probeImage(kHostile + "wide-16385.png");
    ADD_FAILURE() << "wide-16385.png was probed";
  } catch (const ImageInputError& e) {
    EXPECT_NE(std::string(e.what()).find("is 16385x1: raytex reads images of at most 16384 a side"), std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(h = probeImage(kHostile + "wide-16384.png"));
  EXPECT_EQ(h.width, 16384);
}

// libpng maps an index past the palette to whatever follows it in memory (stb_image did the
// same with uninitialised stack memory, so renders differed run to run): refused.
TEST(ImageLoad, PaletteIndexPastThePaletteIsRefused) {
  std::string error = loadError(kHostile + "palette-out-of-range.png");
  EXPECT_NE(error.find("pixel (2, 0) uses colour 2 of a palette of 2"), std::string::npos) << error;
}

// Valid palette images expand to the palette's colours, tRNS giving alpha (255 past its end),
// at every bit depth's byte layout (8 bits here).
TEST(ImageLoad, PaletteExpandsWithTransparency) {
  fs::path dir = freshTempDir("image_load_palette");
  writeFile(dir / "p.png", pngFile(3, 2, 3, std::string{0, 1, 2, 2, 1, 0},
                                    std::string("\xff\x00\x00\x00\xff\x00\x00\x00\xff", 9),
                                    std::string("\x80", 1)));
  ImageRGBA8 image;
  ASSERT_NO_THROW(image = loadImage((dir / "p.png").string()));
  std::vector<uint8_t> want = {255, 0, 0, 128, 0, 255, 0, 255, 0, 0, 255, 255,
                               0,   0, 255, 255, 0, 255, 0, 255, 255, 0, 0, 128};
  EXPECT_EQ(image.pixels, want);
}

TEST(ImageLoad, GrayAndRgbBecomeOpaqueRgba) {
  fs::path dir = freshTempDir("image_load_gray");
  writeFile(dir / "g.png", pngFile(2, 1, 0, std::string{10, char(200)}));
  writeFile(dir / "c.png", pngFile(1, 1, 2, std::string{1, 2, 3}));
  ImageRGBA8 image;
  ASSERT_NO_THROW(image = loadImage((dir / "g.png").string()));
  EXPECT_EQ(image.pixels, (std::vector<uint8_t>{10, 10, 10, 255, 200, 200, 200, 255}));
  ASSERT_NO_THROW(image = loadImage((dir / "c.png").string()));
  EXPECT_EQ(image.pixels, (std::vector<uint8_t>{1, 2, 3, 255}));
}

// libjpeg-turbo only warns on a truncated file (and decodes grey for the rest): a warning is an
// error here, and nothing is printed by the library.
TEST(ImageLoad, TruncatedJpegIsRefused) {
  EXPECT_NE(loadError(kHostile + "truncated.jpg").find("Premature end of JPEG file"), std::string::npos);
}

// Every cut of a PNG before its IEND is refused (the last 12 bytes are the IEND chunk).
TEST(ImageLoad, TruncatedPngIsRefusedAtEveryLength) {
  std::string png = readFile(kSourceDir + "/textures/uv_grid.png");
  fs::path dir = freshTempDir("image_load_cut");
  // The control: the whole file decodes, so each refusal below is the cut's doing (an empty or
  // missing file would be refused at every length too).
  writeFile(dir / "whole.png", png);
  ImageRGBA8 whole;
  ASSERT_NO_THROW(whole = loadImage((dir / "whole.png").string()));
  for (size_t length : {size_t(0), size_t(8), size_t(30), size_t(100), png.size() / 2, png.size() - 13, png.size() - 1}) {
    writeFile(dir / "cut.png", png.substr(0, length));
    EXPECT_THROW(loadImage((dir / "cut.png").string()), ImageInputError) << length << " bytes";
  }
}

// A FIFO (or any non-regular file) as an image is refused at once: opening it for reading would
// block until a writer came.
TEST(ImageLoad, FifoIsRefusedWithoutBlocking) {
  fs::path dir = freshTempDir("image_load_fifo");
  std::string fifo = (dir / "pipe.png").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  auto result = std::make_shared<std::promise<std::string>>();
  std::future<std::string> error = result->get_future();
  std::thread([fifo, result] {
    try {
      loadImage(fifo);
      result->set_value("loaded");
    } catch (const ImageInputError& e) {
      result->set_value(e.what());
    }
  }).detach();
  ASSERT_EQ(error.wait_for(std::chrono::seconds(5)), std::future_status::ready) << "loadImage blocked on a FIFO";
  EXPECT_NE(error.get().find("not a regular file"), std::string::npos);
  EXPECT_NE(loadError(dir.string() + "/").find("not a regular file"), std::string::npos);
}

PackOptions budget(bool mipmaps, uint32_t maxImageMiB) {
  PackOptions pack;
  pack.mipmaps = mipmaps;
  pack.maxImageMiB = maxImageMiB;
  return pack;
}
PackOptions noMipmaps() { return budget(false, kDefaultMaxImageMiB); }

// A 16384x1 and a 1x16384 PNG (208 bytes) at their own sizes: 128 KiB on the GPU (main's one
// array of layers at the largest size made them 2 GiB and refused them).
TEST(SceneImages, WideAndTallImagesTakeTheirOwnSizes) {
  Scene scene = parseSceneText("material wide { texture = image { file = \"images/wide-16384.png\"; } }\n"
                               "material tall { texture = image { file = \"images/tall-16384.png\"; } }\n"
                               "sphere { radius = 1; wide; }\nsphere { center = (3, 0, 0); radius = 1; tall; }\n",
                               kSourceDir + "/tests/malformed/wide_and_tall.cfg");
  EXPECT_EQ(imageUploadBytes(probeSceneImages(scene, {0, 1}, false, 1), false), uint64_t(16384) * 4 * 2);
  GpuScene g = buildGpuScene(scene, 8, 8, noMipmaps());
  ASSERT_EQ(g.imageChains.size(), 2u);
  EXPECT_EQ(g.imageChains[1].width, 1);
  EXPECT_EQ(g.imageChains[1].height, 16384);
}

// A 16384x16384 header (45 bytes, no pixel data) is 1 GiB: refused from its header, at its
// `file` value, before anything is decoded, by both renderers.
TEST(SceneImages, ImagesOverTheBudgetAreRefusedBeforeDecoding) {
  Scene scene = parseSceneFile(kSourceDir + "/tests/malformed/image-over-budget.cfg");
  try {
    buildGpuScene(scene, 8, 8, noMipmaps());
    FAIL() << "expected a SceneError";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc.line, 4);
    EXPECT_EQ(e.loc.column, 42);
    EXPECT_NE(std::string(e.what()).find("header-16384.png' (16384x16384) brings the scene's images to 1024.1 MiB on "
                                         "the GPU (2 images at their own sizes, 4 bytes a texel), over the budget of "
                                         "512 MiB (--max-image-mib N raises it)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(loadReferenceImages(scene), SceneError);  // --reference: the same check
}

Scene earthAndGridScene() {
  return parseSceneText(
      "material a { texture = image { file = \"../textures/earth.jpg\"; }; }\n"
      "material b { texture = image { file = \"../textures/uv_grid.png\"; }; }\n"
      "sphere { center = (0, 0, 0); radius = 1; a; }\n"
      "sphere { center = (3, 0, 0); radius = 1; b; }\n",
      kSourceDir + "/scenes/budget_test.cfg");
}

// The count is the sum of the images' own chains, 4 bytes a texel: earth.jpg (2048x1024) and
// uv_grid.png (512x256) make 8.5 MiB, 11.33 MiB with their mip levels (on main's one array of
// layers at the largest size they counted 16 and 21.3 MiB).
TEST(SceneImages, BudgetCountsWhatIsUploaded) {
  Scene scene = earthAndGridScene();
  std::vector<SceneImage> images = probeSceneImages(scene, {0, 1}, false, 16);
  EXPECT_EQ(imageUploadBytes(images, false), uint64_t(2048 * 1024 + 512 * 256) * 4);
  EXPECT_EQ(imageChainBytes(images[1].header, true), uint64_t(4) * (512 * 256 + 256 * 128 + 128 * 64 + 64 * 32 +
                                                                    32 * 16 + 16 * 8 + 8 * 4 + 4 * 2 + 2 * 1 + 1 * 1));
  EXPECT_NO_THROW(buildGpuScene(scene, 8, 8, budget(false, 9)));
  EXPECT_THROW(buildGpuScene(scene, 8, 8, budget(true, 11)), SceneError);
  EXPECT_NO_THROW(buildGpuScene(scene, 8, 8, budget(true, 12)));
  EXPECT_THROW(buildGpuScene(scene, 8, 8, budget(false, 8)), SceneError);
  EXPECT_THROW(loadReferenceImages(scene, 8), SceneError);
  EXPECT_EQ(loadReferenceImages(scene, 9).size(), size_t(2));
}

// More than MAX_IMAGES image files: refused at the first one over, at its `file`, before its
// header is read (it need not exist), by both renderers; a file named again counts once.
TEST(SceneImages, MoreImagesThanTheKernelBindsIsASceneError) {
  fs::path dir = freshTempDir("image_count");
  ImageRGBA8 pixel{1, 1, {10, 20, 30, 255}};
  std::vector<uint8_t> png = encodePng(pixel);
  std::string text;
  for (int i = 0; i <= MAX_IMAGES; ++i) {
    std::string name = "i" + std::to_string(i) + ".png";
    if (i < MAX_IMAGES)
      std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(png.data()), long(png.size()));
    text += "material m" + std::to_string(i) + " { texture = image { file = \"" + name + "\"; }; }\n";
  }
  std::string sixteen = text + "material again { texture = image { file = \"i0.png\"; }; }\n";
  for (int i = 0; i < MAX_IMAGES; ++i) sixteen += "sphere { center = (" + std::to_string(3 * i) + ", 0, 0); m" + std::to_string(i) + "; }\n";
  sixteen += "sphere { center = (0, 5, 0); again; }\n";
  EXPECT_EQ(buildGpuScene(parseSceneText(sixteen, (dir / "s.cfg").string()), 8, 8).images.size(), size_t(MAX_IMAGES));
  Scene over = parseSceneText(sixteen + "sphere { center = (0, 9, 0); m16; }\n", (dir / "s.cfg").string());
  try {
    buildGpuScene(over, 8, 8);
    ADD_FAILURE() << "17 image files accepted";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.loc.line, 17);
    EXPECT_NE(std::string(e.what()).find("i16.png' is the scene's 17th image file; raytex renders at most 16"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(loadReferenceImages(over), SceneError);
}

// After the device is created: an image over its maxImageDimension2D (16384 on lavapipe, so
// the header check stops larger ones first) is named, and uploadScene throws it (exit 1).
TEST(SceneImages, DeviceLimitsNameTheImageOverThem) {
  GpuScene g = buildGpuScene(earthAndGridScene(), 8, 8, noMipmaps());
  EXPECT_EQ(imagesOverDeviceLimits(g.images, 2048), "");
  std::string over = imagesOverDeviceLimits(g.images, 1024);
  EXPECT_NE(over.find("earth.jpg' is 2048x1024: the device's images are at most 1024 a side (maxImageDimension2D)"),
            std::string::npos)
      << over;
}

}  // namespace
