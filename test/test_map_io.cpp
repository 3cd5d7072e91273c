// Tests of the map readers (include/eaci/io/map_io.hpp) and of OccupancyMap's world <-> cell mapping.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include "eaci/io/map_io.hpp"
#include "eaci/io/occupancy_map.hpp"
#include "test_support.hpp"

namespace eaci {
namespace {

namespace fs = std::filesystem;

constexpr std::uint8_t F = kFreeValue;
constexpr std::uint8_t O = kOccupiedValue;
constexpr std::uint8_t U = kUnknownValue;

// ------------------------------------------------------------------ helpers

// The message of the MapLoadError thrown by `load`, or "" (and a test failure) if none is.
std::string loadError(const std::function<void()>& load) {
  try {
    load();
  } catch (const MapLoadError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected a MapLoadError";
  return "";
}

// Every part appears in the message, and the message is one line.
::testing::AssertionResult messageHas(const std::string& message, std::initializer_list<std::string> parts) {
  if (message.find('\n') != std::string::npos) return ::testing::AssertionFailure() << "not one line: " << message;
  for (const std::string& part : parts) {
    if (message.find(part) == std::string::npos) {
      return ::testing::AssertionFailure() << "'" << part << "' missing from: " << message;
    }
  }
  return ::testing::AssertionSuccess();
}

std::string bytesOf(std::initializer_list<int> values) {
  std::string bytes;
  for (int value : values) bytes.push_back(static_cast<char>(value));
  return bytes;
}

std::string pgmP5(int width, int height, const std::string& raster, int maxval = 255) {
  return "P5\n" + std::to_string(width) + " " + std::to_string(height) + "\n" + std::to_string(maxval) + "\n" + raster;
}

// ---- a minimal PNG writer (8-bit grey, stored deflate block) to test the stb_image path

std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (unsigned char byte : bytes) {
    crc ^= byte;
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

std::uint32_t adler32(const std::string& bytes) {
  std::uint32_t a = 1, b = 0;
  for (unsigned char byte : bytes) {
    a = (a + byte) % 65521u;
    b = (b + a) % 65521u;
  }
  return (b << 16) | a;
}

std::string bigEndian32(std::uint32_t value) {
  return bytesOf({static_cast<int>(value >> 24), static_cast<int>((value >> 16) & 0xFF),
                  static_cast<int>((value >> 8) & 0xFF), static_cast<int>(value & 0xFF)});
}

std::string pngChunk(const std::string& type, const std::string& data) {
  return bigEndian32(static_cast<std::uint32_t>(data.size())) + type + data + bigEndian32(crc32(type + data));
}

// PNG colour types: 0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA; `channels` bytes per pixel.
std::string png(int width, int height, int colour_type, int channels, const std::vector<std::uint8_t>& pixels,
                int bit_depth = 8) {
  std::string scanlines;
  const int row_bytes = width * channels;
  for (int row = 0; row < height; ++row) {
    scanlines.push_back('\0');  // filter type None
    scanlines.append(pixels.begin() + row * row_bytes, pixels.begin() + (row + 1) * row_bytes);
  }
  const auto length = static_cast<int>(scanlines.size());
  const std::string zlib = bytesOf({0x78, 0x01, 0x01, length & 0xFF, length >> 8, ~length & 0xFF, (~length >> 8) & 0xFF}) +
                           scanlines + bigEndian32(adler32(scanlines));
  const std::string header = bigEndian32(static_cast<std::uint32_t>(width)) +
                             bigEndian32(static_cast<std::uint32_t>(height)) + bytesOf({bit_depth, colour_type, 0, 0, 0});
  return bytesOf({0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}) + pngChunk("IHDR", header) + pngChunk("IDAT", zlib) +
         pngChunk("IEND", "");
}

std::string greyPng(int width, int height, const std::vector<std::uint8_t>& pixels) {
  return png(width, height, 0, 1, pixels);
}

// A fresh directory per test under the build directory, removed afterwards.
class MapIoFiles : public eaci::test::ScratchDirTest {
 protected:
  MapIoFiles() : ScratchDirTest("test_map_io_tmp") {}

  std::string write(const std::string& name, const std::string& bytes) const {
    const fs::path path = dir_ / name;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
    return path.string();
  }

};

// A 3 x 2 image and its trinary cells under the default thresholds:
//   v = 0, 89 -> occupied (p = 1, 0.651 > 0.65); 90 -> unknown (p = 0.647);
//   205 -> unknown (p = 0.19608, not < 0.196); 206, 254 -> free (p = 0.192, 0.004).
const std::string kSampleRaster = bytesOf({0, 89, 90, 205, 206, 254});
const std::vector<std::uint8_t> kSampleCells = {O, O, U, U, F, F};
// With negate, p = v / 255: 0 -> free; 89, 90 -> unknown (p = 0.35); 205, 206, 254 -> occupied (p >= 0.80).
const std::vector<std::uint8_t> kSampleCellsNegated = {F, U, U, O, O, O};

// ------------------------------------------------------------------ PGM

TEST(ParsePgm, BinaryEightBitKeepsPixelsRowMajorTopFirst) {
  const GrayImage image = parsePgm(pgmP5(3, 2, kSampleRaster));
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 89, 90, 205, 206, 254}));
}

TEST(ParsePgm, AsciiWithCommentsAnywhereInTheHeader) {
  const GrayImage image = parsePgm("P2 # magic\n# made by hand\n3# width\n2\n# maxval next\n255\n0 128 255\n  10\t20\r\n30\n");
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 128, 255, 10, 20, 30}));
}

TEST(ParsePgm, SixteenBitBinaryIsBigEndianAndScaled) {
  // 0x0000 -> 0, 0xFFFF -> 255, 0x8000 = 32768 -> round(32768 * 255 / 65535) = 128, 0x0101 = 257 -> 1.
  const GrayImage image = parsePgm(pgmP5(2, 2, bytesOf({0x00, 0x00, 0xFF, 0xFF, 0x80, 0x00, 0x01, 0x01}), 65535));
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 255, 128, 1}));
}

TEST(ParsePgm, SmallAndLargeMaxvalAreScaledToByte) {
  // maxval 15: 15 -> 255, 7 -> round(119.0) = 119; maxval 1000: 500 -> round(127.5) = 128.
  EXPECT_EQ(parsePgm("P2 3 1 15\n15 7 0\n").pixels, (std::vector<std::uint8_t>{255, 119, 0}));
  EXPECT_EQ(parsePgm("P2 2 1 1000\n500 1000\n").pixels, (std::vector<std::uint8_t>{128, 255}));
  EXPECT_EQ(parsePgm(pgmP5(2, 1, bytesOf({0x01, 0xF4, 0x03, 0xE8}), 1000)).pixels,
            (std::vector<std::uint8_t>{128, 255}));
}

TEST(ParsePgm, ExtraBytesAfterTheRasterAreIgnored) {
  EXPECT_EQ(parsePgm(pgmP5(1, 1, bytesOf({7, 8, 9}))).pixels, (std::vector<std::uint8_t>{7}));
}

TEST(ParsePgm, WrongMagicIsRefused) {
  for (const std::string bytes : {"", "P", "P6\n1 1\n255\n\x01\x02\x03", "P3 1 1 255 1 2 3", "XX 1 1 255\n\x01"}) {
    EXPECT_TRUE(messageHas(loadError([&] { parsePgm(bytes, "bad.pgm"); }), {"bad.pgm", "magic"})) << bytes;
  }
}

TEST(ParsePgm, TruncatedHeaderOrRasterIsRefused) {
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 2", "t.pgm"); }), {"t.pgm", "truncated", "height"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 2 2 255\n\x01\x02\x03", "t.pgm"); }),
                         {"t.pgm", "truncated", "expected 4 bytes", "found 3"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm(pgmP5(2, 1, bytesOf({0, 1, 2}), 65535), "t.pgm"); }),
                         {"truncated", "expected 4 bytes"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 2 255\n1 2 3", "t.pgm"); }), {"t.pgm", "truncated"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 2 255\n1 2 3    ", "t.pgm"); }), {"found 3 of 4"}));
  // A huge header with no data fails on the size check, not on an allocation.
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 8192 8192 255\n", "t.pgm"); }), {"truncated"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 8192 8192 255\n0", "t.pgm"); }), {"truncated"}));
}

TEST(ParsePgm, WhitespaceMustFollowEveryHeaderField) {
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 1 1 255", "w.pgm"); }), {"w.pgm", "whitespace", "maxval"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 1 1 255x", "w.pgm"); }), {"whitespace after maxval", "'x'"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P51 1 255\n\x01", "w.pgm"); }), {"whitespace before width"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 1x 1 255\n\x01", "w.pgm"); }), {"whitespace before height"}));
}

TEST(ParsePgm, BadSizesAndMaxvalAreRefused) {
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 0 2 255\n", "s.pgm"); }), {"s.pgm", "0 x 2", "no cells"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 2 0 255\n", "s.pgm"); }), {"no cells"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 -1 2 255\n", "s.pgm"); }), {"s.pgm", "expected width", "'-'"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 2 2 0\n", "s.pgm"); }), {"maxval"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 2 2 65536\n", "s.pgm"); }), {"maxval", "65535"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 1 1.5\n1 1\n", "s.pgm"); }), {"whitespace after maxval"}));
}

TEST(ParsePgm, SizesBeyondTheCellLimitAreRefusedWithoutOverflow) {
  // Each field alone too large (would overflow 32-bit arithmetic).
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 4294967295 4294967295 255\n", "big.pgm"); }),
                         {"big.pgm", "width", "larger than"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 99999999999999999999999999 1 255\n", "big.pgm"); }),
                         {"width", "larger than"}));
  // Each field acceptable, the product (2^32, 2^27) not.
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 65536 65536 255\n", "big.pgm"); }),
                         {"big.pgm", "65536 x 65536", "limit"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P5 67108864 2 255\n", "big.pgm"); }), {"limit"}));
}

TEST(ParsePgm, ValuesAboveMaxvalAreRefused) {
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 1 100\n50 101\n", "v.pgm"); }), {"v.pgm", "pixel 1", "maxval 100"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 1 1 255\n99999999999999999999\n", "v.pgm"); }), {"maxval"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm(pgmP5(2, 1, bytesOf({5, 200}), 100), "v.pgm"); }), {"pixel 1", "200"}));
}

TEST(ParsePgm, AsciiRasterAcceptsOnlyNumbersAndWhitespace) {
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 1 255\n1 x\n", "a.pgm"); }), {"a.pgm", "pixel 1", "'x'"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 1 255\n1 -2\n", "a.pgm"); }), {"'-'"}));
  EXPECT_TRUE(messageHas(loadError([] { parsePgm("P2 2 1 255\n1 2x\n", "a.pgm"); }), {"after the number"}));
}

TEST(ParsePgm, EveryTruncationOfAValidFileFailsCleanly) {
  const std::vector<std::string> files = {pgmP5(3, 2, kSampleRaster), "P2\n# c\n3 2\n255\n0 89 90\n205 206 7\n",
                                          pgmP5(2, 1, bytesOf({1, 2, 3, 4}), 65535)};
  for (const std::string& file : files) {
    ASSERT_NO_THROW(parsePgm(file));
    for (std::size_t length = 0; length + 1 < file.size(); ++length) {
      EXPECT_THROW(parsePgm(file.substr(0, length)), MapLoadError) << "length " << length;
    }
  }
}

// ------------------------------------------------------------------ other images

TEST(DecodeImage, PngIsDecodedAsGrey) {
  const GrayImage image = decodeImage(greyPng(3, 2, {0, 89, 90, 205, 206, 254}), "tiny.png");
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 89, 90, 205, 206, 254}));
}

TEST(DecodeImage, PgmIsRecognisedByContent) {
  EXPECT_EQ(decodeImage(pgmP5(3, 2, kSampleRaster)).pixels.size(), 6u);
}

TEST(DecodeImage, UnknownOrCorruptImagesAreRefused) {
  EXPECT_TRUE(messageHas(loadError([] { decodeImage("hello world", "x.img"); }), {"x.img", "unrecognised image format"}));
  EXPECT_TRUE(messageHas(loadError([] { decodeImage("", "x.img"); }), {"x.img"}));
  // JPEG and binary PPM are refused on purpose (see decodeImage).
  EXPECT_TRUE(messageHas(loadError([] { decodeImage("\xff\xd8\xff\xe0", "x.jpg"); }), {"x.jpg", "unrecognised"}));
  EXPECT_TRUE(messageHas(loadError([] { decodeImage("P6 1 1 255\n\x01\x02\x03", "x.ppm"); }), {"x.ppm", "unrecognised"}));
  const std::string png = greyPng(3, 2, {0, 89, 90, 205, 206, 254});
  EXPECT_TRUE(messageHas(loadError([&] { decodeImage(png.substr(0, 20), "x.png"); }), {"x.png", "cannot decode"}));
}

TEST(DecodeImage, DamagedPngsNeverCrash) {
  const std::string png = greyPng(4, 3, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  std::mt19937 random(12345);
  for (int trial = 0; trial < 2000; ++trial) {
    std::string damaged = png;
    const int flips = 1 + static_cast<int>(random() % 4);
    for (int i = 0; i < flips; ++i) damaged[random() % damaged.size()] = static_cast<char>(random() % 256);
    damaged.resize(damaged.size() - random() % 8);
    try {
      const GrayImage image = decodeImage(damaged);
      EXPECT_EQ(image.pixels.size(), static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
    } catch (const MapLoadError&) {
    }
  }
}

// ------------------------------------------------------------------ thresholds

TEST(ThresholdImage, MapServerTrinaryRule) {
  GrayImage image{3, 2, {0, 89, 90, 205, 206, 254}};
  EXPECT_EQ(thresholdImage(image, MapServerThresholds{}), kSampleCells);
  MapServerThresholds negated;
  negated.negate = true;
  image.pixels = {0, 49, 50, 165, 166, 255};  // p = 0, 0.192, 0.196078, 0.647, 0.651, 1
  EXPECT_EQ(thresholdImage(image, negated), (std::vector<std::uint8_t>{F, F, U, U, O, O}));
}

TEST(ThresholdImage, ValuesExactlyAtAThresholdAreUnknown) {
  // 153 / 255 == 0.6 and 51 / 255 == 0.2 exactly; the comparisons are strict.
  MapServerThresholds thresholds;
  thresholds.occupied_thresh = 0.6;
  thresholds.free_thresh = 0.2;
  const GrayImage image{4, 1, {101, 102, 204, 205}};  // p = 0.604, 0.6, 0.2, 0.196
  EXPECT_EQ(thresholdImage(image, thresholds), (std::vector<std::uint8_t>{O, U, U, F}));
}

// ------------------------------------------------------------------ map_server YAML

TEST_F(MapIoFiles, YamlWithBinaryPgmGivesThresholdedCellsAndPose) {
  write("map.pgm", pgmP5(3, 2, kSampleRaster));
  const std::string yaml = write("map.yaml",
                                 "image: map.pgm\nresolution: 0.1\norigin: [-1.5, 2.0, 0.3]\n"
                                 "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const OccupancyMap map = loadMapServerYaml(yaml);
  EXPECT_EQ(map.width, 3);
  EXPECT_EQ(map.height, 2);
  EXPECT_DOUBLE_EQ(map.resolution, 0.1);
  EXPECT_DOUBLE_EQ(map.origin.x(), -1.5);
  EXPECT_DOUBLE_EQ(map.origin.y(), 2.0);
  EXPECT_DOUBLE_EQ(map.origin_yaw, 0.3);
  EXPECT_EQ(map.cells, kSampleCells);
}

TEST_F(MapIoFiles, YamlDefaultsAreMapServerDefaults) {
  write("map.pgm", pgmP5(3, 2, kSampleRaster));
  const std::string yaml = write("map.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(loadMapServerYaml(yaml).cells, kSampleCells);
}

TEST_F(MapIoFiles, YamlNegateAsIntegerOrBool) {
  write("map.pgm", pgmP5(3, 2, kSampleRaster));
  for (const std::string negate : {"1", "true"}) {
    const std::string yaml = write("map.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: " + negate + "\n");
    EXPECT_EQ(loadMapServerYaml(yaml).cells, kSampleCellsNegated) << negate;
  }
  const std::string yaml = write("map.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\nnegate: false\n");
  EXPECT_EQ(loadMapServerYaml(yaml).cells, kSampleCells);
}

TEST_F(MapIoFiles, YamlThresholdsAreApplied) {
  write("map.pgm", pgmP5(4, 1, bytesOf({101, 102, 204, 205})));
  const std::string yaml = write(
      "map.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\noccupied_thresh: 0.6\nfree_thresh: 0.2\n");
  EXPECT_EQ(loadMapServerYaml(yaml).cells, (std::vector<std::uint8_t>{O, U, U, F}));
}

TEST_F(MapIoFiles, YamlWithAsciiPgmAndPng) {
  write("ascii.pgm", "P2\n3 2\n255\n0 89 90\n205 206 254\n");
  write("tiny.png", greyPng(3, 2, {0, 89, 90, 205, 206, 254}));
  for (const std::string image : {"ascii.pgm", "tiny.png"}) {
    const std::string yaml = write("map.yaml", "image: " + image + "\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n");
    EXPECT_EQ(loadMapServerYaml(yaml).cells, kSampleCells) << image;
  }
}

TEST_F(MapIoFiles, YamlImagePathIsRelativeToTheYamlFileUnlessAbsolute) {
  const std::string image = write("pictures/room.pgm", pgmP5(3, 2, kSampleRaster));
  const std::string relative = write("maps/a.yaml", "image: ../pictures/room.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(loadMapServerYaml(relative).cells, kSampleCells);
  const std::string absolute = write("maps/b.yaml", "image: " + image + "\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_EQ(loadMapServerYaml(absolute).cells, kSampleCells);
  // Relative to the YAML file, not to the working directory: "room.pgm" is not next to maps/c.yaml.
  const std::string wrong = write("maps/c.yaml", "image: room.pgm\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_TRUE(messageHas(loadError([&] { loadMapServerYaml(wrong); }),
                         {wrong, (dir_ / "maps" / "room.pgm").string(), "No such file"}));
}

TEST_F(MapIoFiles, YamlModesAreAcceptedOrRefused) {
  write("map.pgm", pgmP5(3, 2, kSampleRaster));
  for (const std::string mode : {"", "mode: trinary\n"}) {
    const std::string yaml = write("map.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n" + mode);
    const OccupancyMap map = loadMapServerYaml(yaml);
    EXPECT_EQ(map.cells, kSampleCells) << mode;
    EXPECT_EQ(map.values, CellValues::kOccupancy) << mode;
  }
  const std::string fancy = write("fancy.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: fancy\n");
  EXPECT_TRUE(messageHas(loadError([&] { loadMapServerYaml(fancy); }), {fancy, "'mode'", "'fancy'", "trinary or raw"}));
  // map_server's scale mode would give occupancies 1..99: refused, never read as trinary.
  const std::string scale = write("scale.yaml", "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\nmode: scale\n");
  EXPECT_TRUE(messageHas(loadError([&] { loadMapServerYaml(scale); }), {scale, "'mode' is 'scale', which is not supported"}));
}

// ------------------------------------------------------------------ raw mode

// Costs across costmap_2d's range; in trinary mode these pixels would be O, O, O, O, U, F, F, F.
const std::vector<std::uint8_t> kCostPixels = {0, 1, 100, 252, 253, 254, 255, 128};

TEST_F(MapIoFiles, RawModeKeepsEveryPixelAsACostmapCost) {
  write("costs.pgm", pgmP5(4, 2, std::string(kCostPixels.begin(), kCostPixels.end())));
  // The thresholds are present (map_server requires them) and have no effect in raw mode.
  const std::string yaml = write("costs.yaml", "image: costs.pgm\nmode: raw\nresolution: 0.5\norigin: [1, 2, 0]\n"
                                               "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const OccupancyMap map = loadMapServerYaml(yaml);
  EXPECT_EQ(map.values, CellValues::kCostmapCosts);
  EXPECT_EQ(map.cells, kCostPixels);

  // Read as costmap_2d costs: 253 and 254 are obstacles, 255 is unknown, the rest are costs.
  const GridView view = map.view();
  EXPECT_EQ(view.cost(Cell{0, 0}), 0);
  EXPECT_EQ(view.cost(Cell{0, 1}), 1);
  EXPECT_EQ(view.cost(Cell{0, 2}), 100);
  EXPECT_EQ(view.cost(Cell{0, 3}), 252);
  EXPECT_EQ(view.cost(Cell{1, 3}), 128);
  for (const Cell c : {Cell{0, 0}, Cell{0, 1}, Cell{0, 2}, Cell{0, 3}, Cell{1, 3}}) EXPECT_FALSE(view.isObstacle(c));
  EXPECT_TRUE(view.isObstacle(Cell{1, 0}));  // 253
  EXPECT_TRUE(view.isObstacle(Cell{1, 1}));  // 254
  EXPECT_TRUE(view.isObstacle(Cell{1, 2}));  // 255, unknown as obstacle
  const GridView unknown_free = map.view(UnknownPolicy::kExpensive);
  EXPECT_FALSE(unknown_free.isObstacle(Cell{1, 2}));
  EXPECT_EQ(unknown_free.cost(Cell{1, 2}), 252);  // the dearest passable cost: lethal 253 - 1
  // A lethal cost of 200 makes the 252 cell an obstacle too.
  EXPECT_TRUE(map.view(UnknownPolicy::kObstacle, 200).isObstacle(Cell{0, 3}));
  EXPECT_FALSE(map.view(UnknownPolicy::kObstacle, 200).isObstacle(Cell{0, 2}));
}

TEST_F(MapIoFiles, RawModeImageTopRowIsTheMapTop) {
  write("column.pgm", pgmP5(1, 2, bytesOf({10, 20})));
  const OccupancyMap map = loadMapServerYaml(write("column.yaml", "image: column.pgm\nmode: raw\nresolution: 1\norigin: [0, 0, 0]\n"));
  // (0.5, 0.5) m is in the bottom cell (next to the origin): the image's last row.
  const auto bottom = map.worldToCell({0.5, 0.5});
  ASSERT_TRUE(bottom.has_value());
  EXPECT_EQ(map.view().value(*bottom), 20);
  EXPECT_EQ(map.view().value(*map.worldToCell({0.5, 1.5})), 10);
}

TEST_F(MapIoFiles, RawModeNegateTakes255MinusThePixel) {
  write("costs.pgm", pgmP5(4, 2, std::string(kCostPixels.begin(), kCostPixels.end())));
  const OccupancyMap map = loadMapServerYaml(write("costs.yaml", "image: costs.pgm\nmode: raw\nresolution: 1\n"
                                                                 "origin: [0, 0, 0]\nnegate: 1\n"));
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{255, 254, 155, 3, 2, 1, 0, 127}));
}

TEST(DecodeRawImage, PngChannelsAreAveragedWithoutAlphaAndTruncated) {
  // map_server: mean of the colour channels, alpha not counted, then (with negate) 255 - mean,
  // truncated: (10 + 20 + 31) / 3 = 20.33 -> 20, negated 234.67 -> 234.
  EXPECT_EQ(decodeRawImage(png(1, 1, 2, 3, {10, 20, 31}), false).pixels, std::vector<std::uint8_t>{20});
  EXPECT_EQ(decodeRawImage(png(1, 1, 2, 3, {10, 20, 31}), true).pixels, std::vector<std::uint8_t>{234});
  EXPECT_EQ(decodeRawImage(png(2, 1, 6, 4, {10, 20, 30, 0, 3, 4, 4, 255}), false).pixels,
            (std::vector<std::uint8_t>{20, 3}));  // 11 / 3 = 3.67 -> 3
  EXPECT_EQ(decodeRawImage(png(2, 1, 4, 2, {77, 0, 252, 9}), false).pixels, (std::vector<std::uint8_t>{77, 252}));
  EXPECT_EQ(decodeRawImage(greyPng(3, 1, {0, 128, 255}), false).pixels, (std::vector<std::uint8_t>{0, 128, 255}));
  // ASCII PGM with maxval 255: the values as they are.
  EXPECT_EQ(decodeRawImage("P2\n3 1\n255\n0 7 253\n", false).pixels, (std::vector<std::uint8_t>{0, 7, 253}));
}

TEST(DecodeRawImage, ImagesWhoseBytesAreNotTheValuesAreRefused) {
  EXPECT_TRUE(messageHas(loadError([] { decodeRawImage(pgmP5(2, 1, bytesOf({0, 50}), 100), false, "c.pgm"); }),
                         {"c.pgm", "maxval is 100", "raw mode reads 8-bit images only"}));
  EXPECT_TRUE(messageHas(loadError([] { decodeRawImage(png(1, 1, 0, 2, {0, 9}, 16), false, "w.png"); }),
                         {"w.png", "16 bits per channel"}));
  EXPECT_TRUE(messageHas(loadError([] { decodeRawImage(png(1, 1, 3, 1, {0}), false, "p.png"); }),
                         {"p.png", "palette"}));
  EXPECT_TRUE(messageHas(loadError([] { decodeRawImage("BM" + std::string(60, '\0'), false, "b.bmp"); }),
                         {"b.bmp", "not a PGM or PNG"}));
}

TEST_F(MapIoFiles, RawModeErrorsNameTheYamlAndTheImage) {
  write("deep.pgm", pgmP5(2, 1, bytesOf({0, 50}), 100));
  const std::string yaml = write("deep.yaml", "image: deep.pgm\nmode: raw\nresolution: 1\norigin: [0, 0, 0]\n");
  EXPECT_TRUE(messageHas(loadError([&] { loadMapServerYaml(yaml); }), {yaml, "deep.pgm", "maxval is 100"}));
}

// Writes map.pgm and a YAML with `body`, and returns the load error.
class YamlErrors : public MapIoFiles {
 protected:
  std::string errorFor(const std::string& body) {
    write("map.pgm", pgmP5(3, 2, kSampleRaster));
    yaml_ = write("bad.yaml", body);
    return loadError([this] { loadMapServerYaml(yaml_); });
  }
  std::string yaml_;
};

TEST_F(YamlErrors, MissingRequiredKeys) {
  EXPECT_TRUE(messageHas(errorFor("resolution: 1\norigin: [0, 0, 0]\n"), {"bad.yaml", "missing key 'image'"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\norigin: [0, 0, 0]\n"), {"bad.yaml", "missing key 'resolution'"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: 1\n"), {"bad.yaml", "missing key 'origin'"}));
}

TEST_F(YamlErrors, BadResolution) {
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: -0.05\norigin: [0, 0, 0]\n"),
                         {"bad.yaml", "'resolution'", "positive"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: 0\norigin: [0, 0, 0]\n"), {"'resolution'", "positive"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: .inf\norigin: [0, 0, 0]\n"), {"'resolution'", "finite"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: fine\norigin: [0, 0, 0]\n"),
                         {"'resolution'", "number", "fine"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: [1]\norigin: [0, 0, 0]\n"), {"'resolution'", "number"}));
}

TEST_F(YamlErrors, BadOrigin) {
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: 1\norigin: [.nan, 0, 0]\n"),
                         {"bad.yaml", "'origin'", "finite"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: 1\norigin: [0, 0]\n"), {"'origin'", "3 numbers"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: 1\norigin: 0\n"), {"'origin'", "3 numbers"}));
  EXPECT_TRUE(messageHas(errorFor("image: map.pgm\nresolution: 1\norigin: [0, x, 0]\n"), {"'origin'", "number"}));
}

TEST_F(YamlErrors, BadThresholdsAndNegate) {
  const std::string head = "image: map.pgm\nresolution: 1\norigin: [0, 0, 0]\n";
  EXPECT_TRUE(messageHas(errorFor(head + "occupied_thresh: 1.5\n"), {"bad.yaml", "'occupied_thresh'", "between 0 and 1"}));
  EXPECT_TRUE(messageHas(errorFor(head + "free_thresh: -0.1\n"), {"'free_thresh'", "between 0 and 1"}));
  EXPECT_TRUE(messageHas(errorFor(head + "free_thresh: .nan\n"), {"'free_thresh'", "finite"}));
  EXPECT_TRUE(messageHas(errorFor(head + "occupied_thresh: 0.3\nfree_thresh: 0.3\n"),
                         {"free_thresh", "smaller than occupied_thresh"}));
  EXPECT_TRUE(messageHas(errorFor(head + "negate: 2\n"), {"'negate'", "0, 1, true or false"}));
  EXPECT_TRUE(messageHas(errorFor(head + "negate: maybe\n"), {"'negate'"}));
}

TEST_F(YamlErrors, BadImageKey) {
  EXPECT_TRUE(messageHas(errorFor("image: ''\nresolution: 1\norigin: [0, 0, 0]\n"), {"'image'", "empty"}));
  EXPECT_TRUE(messageHas(errorFor("image: [a, b]\nresolution: 1\norigin: [0, 0, 0]\n"), {"'image'", "file name"}));
  const std::string missing = (dir_ / "nowhere.pgm").string();
  EXPECT_TRUE(messageHas(errorFor("image: nowhere.pgm\nresolution: 1\norigin: [0, 0, 0]\n"),
                         {"bad.yaml", "cannot open " + missing, "No such file or directory"}));
  fs::create_directories(dir_ / "folder");
  EXPECT_TRUE(messageHas(errorFor("image: folder\nresolution: 1\norigin: [0, 0, 0]\n"), {"Is a directory"}));
  write("corrupt.pgm", "P5 3 2 255\n\x01");
  EXPECT_TRUE(messageHas(errorFor("image: corrupt.pgm\nresolution: 1\norigin: [0, 0, 0]\n"),
                         {"bad.yaml", "corrupt.pgm", "truncated"}));
}

TEST_F(YamlErrors, NotAMapServerDocument) {
  EXPECT_TRUE(messageHas(errorFor("image: [unclosed\nresolution: 1\n"), {"bad.yaml", "invalid YAML"}));
  EXPECT_TRUE(messageHas(errorFor("- image\n- resolution\n"), {"bad.yaml", "mapping"}));
  EXPECT_TRUE(messageHas(errorFor(""), {"bad.yaml", "mapping"}));
  EXPECT_TRUE(messageHas(errorFor("just text"), {"bad.yaml", "mapping"}));
  EXPECT_TRUE(messageHas(errorFor(std::string(5000, '[')), {"bad.yaml"}));
}

// ------------------------------------------------------------------ 0/1 text matrices

TEST(ParseMatrixText, SeparatorsCommentsAndLineEndingsAllGiveTheSameMap) {
  const std::vector<std::uint8_t> expected = {F, O, O, F, O, F, F, F};
  const std::vector<std::string> texts = {
      "0 1 1 0\n1 0 0 0\n",
      "0,1,1,0\n1, 0 ,0,0",
      "0110\n1000\n",
      "0\t1\t1\t0\n1\t0\t0\t0\n",
      "# a comment line\n\n0 1 1 0   # trailing comment\n   \n1 0 0 0  \t\n\n# the end\n",
      "0 1 1 0\r\n1 0 0 0\r\n",
      "\xEF\xBB\xBF" "01 10\n10 00",
  };
  for (const std::string& text : texts) {
    const OccupancyMap map = parseMatrixText(text);
    EXPECT_EQ(map.width, 4) << text;
    EXPECT_EQ(map.height, 2) << text;
    EXPECT_EQ(map.cells, expected) << text;
    EXPECT_DOUBLE_EQ(map.resolution, 1.0);
    EXPECT_DOUBLE_EQ(map.origin.x(), 0.0);
    EXPECT_DOUBLE_EQ(map.origin.y(), 0.0);
  }
}

TEST(ParseMatrixText, SingleCell) {
  const OccupancyMap map = parseMatrixText("1");
  EXPECT_EQ(map.width, 1);
  EXPECT_EQ(map.height, 1);
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{O}));
}

TEST(ParseMatrixText, RaggedRowsNameTheLineAndBothLengths) {
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("# header\n0 0 0\n0 0\n", "r.txt"); }),
                         {"r.txt", "line 3 has 2 cells", "line 2 has 3"}));
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("00\n00\n\n000", "r.txt"); }), {"line 4 has 3 cells", "line 1 has 2"}));
}

TEST(ParseMatrixText, OtherCharactersNameTheLineAndColumn) {
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("0 1\n0 2\n", "c.txt"); }), {"c.txt", "line 2, column 3", "'2'"}));
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("0;1\n", "c.txt"); }), {"line 1, column 2", "';'"}));
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText(std::string("0 1\n1 \0", 7), "c.txt"); }),
                         {"line 2, column 3", "0x00"}));
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("0 1\n1 -1\n", "c.txt"); }), {"line 2, column 3", "'-'"}));
}

TEST(ParseMatrixText, CommasMustSitBetweenCells) {
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText(",0,1\n", "m.txt"); }), {"line 1, column 1", "','"}));
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("0,,1\n", "m.txt"); }), {"line 1, column 3", "','"}));
  EXPECT_TRUE(messageHas(loadError([] { parseMatrixText("0,1\n0,1, \n", "m.txt"); }), {"line 2, column 4", "','"}));
}

TEST(ParseMatrixText, EmptyInputHasNoCells) {
  for (const std::string text : {"", "\n\n", "   \r\n\t", "# only a comment\n"}) {
    EXPECT_TRUE(messageHas(loadError([&] { parseMatrixText(text, "e.txt"); }), {"e.txt", "map has no cells"}));
  }
}

TEST_F(MapIoFiles, MatrixFromFile) {
  const std::string path = write("m.txt", "0 1\n1 1\n0 0\n");
  const OccupancyMap map = loadMatrixText(path);
  EXPECT_EQ(map.width, 2);
  EXPECT_EQ(map.height, 3);
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{F, O, O, O, F, F}));
  const std::string empty = write("empty.txt", "");
  EXPECT_TRUE(messageHas(loadError([&] { loadMatrixText(empty); }), {empty, "map has no cells"}));
}

// ------------------------------------------------------------------ loadMap and file errors

TEST_F(MapIoFiles, LoadMapDispatchesOnTheExtension) {
  write("map.pgm", pgmP5(3, 2, kSampleRaster));
  const std::string body = "image: map.pgm\nresolution: 0.5\norigin: [0, 0, 0]\n";
  for (const std::string name : {"a.yaml", "b.yml", "c.YAML", "d.Yml"}) {
    EXPECT_EQ(loadMap(write(name, body)).cells, kSampleCells) << name;
  }
  for (const std::string name : {"m.txt", "m.csv", "matrix", "m.yaml.txt"}) {
    EXPECT_EQ(loadMap(write(name, "0 1\n")).cells, (std::vector<std::uint8_t>{F, O})) << name;
  }
}

TEST_F(MapIoFiles, MissingFilesNameThePathAndTheReason) {
  for (const std::string name : {"absent.txt", "absent.yaml"}) {
    const std::string path = (dir_ / name).string();
    EXPECT_EQ(loadError([&] { loadMap(path); }), "cannot open " + path + ": No such file or directory");
  }
  const std::string path = (dir_ / "absent.txt").string();
  EXPECT_TRUE(messageHas(loadError([&] { loadMatrixText(path); }), {"cannot open " + path}));
  EXPECT_TRUE(messageHas(loadError([&] { loadMapServerYaml(path); }), {"cannot open " + path}));
  EXPECT_TRUE(messageHas(loadError([] { loadMap(""); }), {"cannot open"}));
}

TEST_F(MapIoFiles, DirectoriesAndDevicesAreRefused) {
  fs::create_directories(dir_ / "sub.yaml");
  for (const std::string& path : {dir_.string(), (dir_ / "sub.yaml").string()}) {
    EXPECT_EQ(loadError([&] { loadMap(path); }), "cannot open " + path + ": Is a directory");
  }
  if (fs::exists("/dev/zero")) {
    EXPECT_TRUE(messageHas(loadError([] { loadMap("/dev/zero"); }), {"cannot open /dev/zero", "not a regular file"}));
  }
}

// ------------------------------------------------------------------ bundled and benchmark maps

TEST(PaperMapFiles, AllLoadWithTheirSizes) {
  const fs::path dir(eaci::test::mapsDir());
  ASSERT_TRUE(fs::is_directory(dir)) << "the paper's maps are missing: " << dir;
  for (int size : {20, 30, 40, 50}) {
    const std::string name = "paper-" + std::to_string(size) + "x" + std::to_string(size) + ".txt";
    const OccupancyMap map = loadMap((dir / name).string());
    EXPECT_EQ(map.width, size) << name;
    EXPECT_EQ(map.height, size) << name;
    EXPECT_EQ(map.cells.size(), static_cast<std::size_t>(size * size)) << name;
  }
  // First line of paper-20x20.txt: "0 0 0 0 0 0 1 1 1 0 ...".
  const OccupancyMap map = loadMap((dir / "paper-20x20.txt").string());
  const GridView view = map.view();
  EXPECT_TRUE(view.isFree(Cell{0, 0}));
  EXPECT_TRUE(view.isObstacle(Cell{0, 6}));
  EXPECT_TRUE(view.isObstacle(Cell{0, 8}));
  EXPECT_TRUE(view.isFree(Cell{0, 9}));
}

// Cells reachable from `start` by 4-neighbour steps through cells that `blocked` leaves free.
std::vector<bool> reachable(const OccupancyMap& map, Cell start, const std::vector<bool>& blocked) {
  std::vector<bool> seen(map.cells.size(), false);
  const auto index = [&map](Cell c) { return static_cast<std::size_t>(c.row * map.width + c.col); };
  std::deque<Cell> queue{start};
  seen[index(start)] = true;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    for (const Cell next : {Cell{c.row + 1, c.col}, Cell{c.row - 1, c.col}, Cell{c.row, c.col + 1}, Cell{c.row, c.col - 1}}) {
      if (next.row < 0 || next.col < 0 || next.row >= map.height || next.col >= map.width) continue;
      if (blocked[index(next)] || seen[index(next)]) continue;
      seen[index(next)] = true;
      queue.push_back(next);
    }
  }
  return seen;
}

// Obstacles grown by `radius` cells (Euclidean), as a costmap inflates them for the robot.
std::vector<bool> inflatedObstacles(const OccupancyMap& map, int radius) {
  std::vector<bool> blocked(map.cells.size(), false);
  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      if (map.cells[static_cast<std::size_t>(row * map.width + col)] == kFreeValue) continue;
      for (int dr = -radius; dr <= radius; ++dr) {
        for (int dc = -radius; dc <= radius; ++dc) {
          const int r = row + dr, c = col + dc;
          if (dr * dr + dc * dc > radius * radius || r < 0 || c < 0 || r >= map.height || c >= map.width) continue;
          blocked[static_cast<std::size_t>(r * map.width + c)] = true;
        }
      }
    }
  }
  return blocked;
}

TEST(LabMap, IsA96By60MapServerMapWithAWall) {
  const OccupancyMap map = loadMap(std::string(EACI_SOURCE_DIR) + "/maps/lab.yaml");
  ASSERT_EQ(map.width, 96);
  ASSERT_EQ(map.height, 60);
  EXPECT_DOUBLE_EQ(map.resolution, 0.05);
  EXPECT_DOUBLE_EQ(map.origin.x(), 0.0);
  EXPECT_DOUBLE_EQ(map.origin.y(), 0.0);
  EXPECT_DOUBLE_EQ(map.origin_yaw, 0.0);
  for (std::uint8_t value : map.cells) EXPECT_TRUE(value == kFreeValue || value == kOccupiedValue);
  const GridView view = map.view();
  for (int col = 0; col < map.width; ++col) {
    EXPECT_TRUE(view.isObstacle(Cell{0, col}));
    EXPECT_TRUE(view.isObstacle(Cell{59, col}));
  }
  for (int row = 0; row < map.height; ++row) {
    EXPECT_TRUE(view.isObstacle(Cell{row, 0}));
    EXPECT_TRUE(view.isObstacle(Cell{row, 95}));
  }
  // The U (maps/README.md): back wall at columns 56-57, its dead-end inside free.
  EXPECT_TRUE(view.isObstacle(Cell{30, 56}));
  EXPECT_TRUE(view.isObstacle(Cell{22, 42}));
  EXPECT_TRUE(view.isFree(Cell{30, 48}));
}

TEST(LabMap, StartAndGoalAreConnectedForTheInflatedRobot) {
  const OccupancyMap map = loadMap(std::string(EACI_SOURCE_DIR) + "/maps/lab.yaml");
  const auto start = map.worldToCell({0.4, 0.4});
  const auto goal = map.worldToCell({4.4, 2.6});
  ASSERT_TRUE(start && goal);
  EXPECT_EQ(*start, (Cell{51, 8}));
  EXPECT_EQ(*goal, (Cell{7, 88}));
  const std::vector<bool> blocked = inflatedObstacles(map, 4);
  ASSERT_FALSE(blocked[static_cast<std::size_t>(start->row * map.width + start->col)]);
  const std::vector<bool> seen = reachable(map, *start, blocked);
  EXPECT_TRUE(seen[static_cast<std::size_t>(goal->row * map.width + goal->col)]);
  EXPECT_TRUE(seen[static_cast<std::size_t>(30 * map.width + 48)]) << "the inside of the U should be enterable";
}

// ------------------------------------------------------------------ OccupancyMap world <-> cell

TEST(OccupancyMapWorld, WorldToCellAndBack) {
  OccupancyMap map;
  map.width = 3;
  map.height = 4;
  map.resolution = 0.5;
  map.origin = {-1.0, 2.0};
  map.cells.assign(12, kFreeValue);

  // (-0.9, 2.1) is 0.1 m right of and above the origin: the bottom-left cell, row 3 (of 0..3), column 0.
  const auto bottom_left = map.worldToCell({-0.9, 2.1});
  ASSERT_TRUE(bottom_left);
  EXPECT_EQ(*bottom_left, (Cell{3, 0}));
  // (0.4, 3.9): column floor(1.4 / 0.5) = 2, row from the bottom floor(1.9 / 0.5) = 3 -> top-right cell.
  EXPECT_EQ(map.worldToCell({0.4, 3.9}).value(), (Cell{0, 2}));

  const Eigen::Vector2d centre = map.cellToWorld(Cell{3, 0});
  EXPECT_DOUBLE_EQ(centre.x(), -0.75);
  EXPECT_DOUBLE_EQ(centre.y(), 2.25);
  const Eigen::Vector2d top_right = map.cellToWorld(Cell{0, 2});
  EXPECT_DOUBLE_EQ(top_right.x(), 0.25);
  EXPECT_DOUBLE_EQ(top_right.y(), 3.75);

  EXPECT_FALSE(map.worldToCell({-1.01, 2.1}));  // left of the map
  EXPECT_FALSE(map.worldToCell({-0.9, 1.99}));  // below
  EXPECT_FALSE(map.worldToCell({0.5, 2.1}));    // x = right edge: column 3 does not exist
  EXPECT_FALSE(map.worldToCell({-0.9, 4.0}));   // y = top edge
  EXPECT_FALSE(map.worldToCell({std::nan(""), 2.1}));

  for (int row = 0; row < map.height; ++row) {
    for (int col = 0; col < map.width; ++col) {
      const Eigen::Vector2d p = map.cellToWorld(Cell{row, col});
      EXPECT_EQ(map.worldToCell(p).value(), (Cell{row, col}));
    }
  }
}

}  // namespace
}  // namespace eaci
