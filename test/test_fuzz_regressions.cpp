// Regression tests from fuzzing (fuzz/, docs/fuzzing.md): every input a fuzz target found to
// crash, leak, time out or exhaust memory, minimised, fed to the parser as the exact bytes, plus
// the nastiest inputs seen, to pin that each ends in a clean error or a well-formed result.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "../src/tools/cli_args.hpp"
#include "eaci/planner/parameters.hpp"
#include "eaci/io/map_io.hpp"
#include "eaci/io/occupancy_map.hpp"

namespace eaci {
namespace {

// The bytes of a string literal, NULs included, without the terminating one.
template <std::size_t N>
std::string bytes(const char (&literal)[N]) {
  return std::string(literal, N - 1);
}

// The MapLoadError message of `action`, or "" when it does not throw one.
template <typename Action>
std::string mapError(Action action) {
  try {
    action();
  } catch (const MapLoadError& error) {
    return error.what();
  }
  return "";
}

bool contains(const std::string& text, std::initializer_list<const char*> parts) {
  for (const char* part : parts) {
    if (text.find(part) == std::string::npos) return false;
  }
  return true;
}

// fuzz_image, out-of-memory (minimised to 41 bytes): a PNG whose IDAT chunk declares
// 1073741837 bytes. stb_image reserved the declared length before reading it; the chunk
// lengths are now checked against the file first.
const std::string kPngIdatClaims1GiB = bytes(
    "\211PNG\015\012\032\012\000\000\000\015IHDR\000\002\000\000\000\000\000\001\020\000\000"
    "\000\000\201\331\202\025@\000\000\015IDAT");

// fuzz_image, timeout (minimised to 54 bytes, 10.5 s under ASan): a BMP header declaring
// 1048578 x 46 pixels of 24 bits and no pixel data. stb_image read zeros past the end of the
// file and returned a 48-million-cell image; the pixel data is now checked against the file.
const std::string kBmpHeaderOnly1048578x46 = bytes(
    "BMF\000\000\000\000\000\000\0006\000\000\000(\000\000\000\002\000\020\000.\000\000\000\001"
    "\000\030\000\000\000\000\000\020\000\000\000\023$$\275\012\000\000``\000\000NS\377\000\000");

// fuzz_map_yaml, UBSan "null pointer passed as argument 1" in stb_image's stbi__getn (found as
// the image of a map YAML, minimised to 41 bytes): a PNG whose first IDAT chunk is empty.
// stb_image copied the empty chunk to its not yet allocated buffer, memcpy(NULL, p, 0).
const std::string kPngEmptyFirstIdat = bytes(
    "\211PNG\015\012\032\012\000\000\000\015IHDR\000\000\000\003\000\000\000\002\010\000\000"
    "\000\000\270\0379\306\000\000\000\000IDAT");

// fuzz/corpus/image/gray.png: 3 x 2 grey, 8 bit.
const std::string kGrayPng = bytes(
    "\211PNG\015\012\032\012\000\000\000\015IHDR\000\000\000\003\000\000\000\002\010\000\000"
    "\000\000\270\0379\306\000\000\000\020IDATx\332c`h\370\317\360\357\254\000\000\014\247\003["
    "f\210\264[\000\000\000\000IEND\256B`\202");

// fuzz/corpus/image/rgb24.bmp: 2 x 2, 24 bit, rows padded to 8 bytes (black, white / grey, red).
const std::string kRgb24Bmp = bytes(
    "BMF\000\000\000\000\000\000\0006\000\000\000(\000\000\000\002\000\000\000\002\000\000\000"
    "\001\000\030\000\000\000\000\000\020\000\000\000\023\013\000\000\023\013\000\000\000\000"
    "\000\000\000\000\000\000\200\200\200\000\000\377\000\000\000\000\000\377\377\377\000\000");

TEST(FuzzRegression, PngChunkLongerThanTheFileIsRefusedBeforeDecoding) {
  const std::string message = mapError([] { decodeImage(kPngIdatClaims1GiB, "oom.png"); });
  EXPECT_TRUE(contains(message, {"oom.png: ", "truncated PNG", "IDAT", "1073741837"})) << message;
  // Any truncation inside a chunk, not only IDAT.
  EXPECT_TRUE(contains(mapError([] { decodeImage(kGrayPng.substr(0, 50), "cut.png"); }), {"truncated PNG"}));
}

TEST(FuzzRegression, PngWithAnEmptyFirstIdatChunkIsRefused) {
  const std::string message = mapError([] { decodeImage(kPngEmptyFirstIdat, "empty.png"); });
  EXPECT_TRUE(contains(message, {"empty.png: ", "empty first IDAT"})) << message;
  // The same with the real image data after the empty chunk; an empty IDAT after data is fine.
  const std::string empty_idat = bytes("\000\000\000\000IDAT\065\257\006\036");
  const std::size_t first_idat = 33;  // after the signature and IHDR
  const std::string before = kGrayPng.substr(0, first_idat) + empty_idat + kGrayPng.substr(first_idat);
  EXPECT_TRUE(contains(mapError([&] { decodeImage(before, "before.png"); }), {"empty first IDAT"}));
  const std::size_t iend = kGrayPng.size() - 12;
  const std::string after = kGrayPng.substr(0, iend) + empty_idat + kGrayPng.substr(iend);
  EXPECT_EQ(decodeImage(after, "after.png").pixels, (std::vector<std::uint8_t>{0, 128, 255, 254, 205, 16}));
}

TEST(FuzzRegression, PngChunkCheckKeepsValidFiles) {
  const GrayImage image = decodeImage(kGrayPng, "gray.png");
  EXPECT_EQ(image.width, 3);
  EXPECT_EQ(image.height, 2);
  EXPECT_EQ(image.pixels, (std::vector<std::uint8_t>{0, 128, 255, 254, 205, 16}));
  // Bytes after IEND are not looked at.
  EXPECT_EQ(decodeImage(kGrayPng + bytes("\377\377\377\377junk"), "tail.png").pixels, image.pixels);
}

TEST(FuzzRegression, BmpWithoutItsPixelDataIsRefused) {
  const std::string message = mapError([] { decodeImage(kBmpHeaderOnly1048578x46, "timeout.bmp"); });
  EXPECT_TRUE(contains(message, {"timeout.bmp: ", "truncated BMP", "1048578 x 46"})) << message;
  // The last row of the sample without its 2 bytes of padding is still whole; one byte less is not.
  EXPECT_EQ(decodeImage(kRgb24Bmp.substr(0, kRgb24Bmp.size() - 2), "nopad.bmp").pixels.size(), 4u);
  EXPECT_TRUE(contains(mapError([&] { decodeImage(kRgb24Bmp.substr(0, kRgb24Bmp.size() - 3), "cut.bmp"); }),
                       {"cut.bmp: ", "truncated BMP"}));
  EXPECT_TRUE(contains(mapError([] { decodeImage("BM\001\002", "tiny.bmp"); }), {"tiny.bmp: "}));
}

TEST(FuzzRegression, BmpCheckKeepsValidFiles) {
  const GrayImage image = decodeImage(kRgb24Bmp, "rgb24.bmp");
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 2);
  EXPECT_EQ(image.pixels[0], 0);    // black, top left
  EXPECT_EQ(image.pixels[1], 255);  // white
  EXPECT_EQ(image.pixels[2], 128);  // grey, bottom left
}

// A GIF of `width` x `height` screen pixels holding one 1 x 1 frame (pixel index 0): header,
// logical screen with a 2-colour table (black, white), image descriptor, LZW data, trailer.
std::string gifWithScreen(int width, int height) {
  std::string gif = "GIF89a";
  gif += {static_cast<char>(width & 0xff), static_cast<char>(width >> 8 & 0xff), static_cast<char>(height & 0xff),
          static_cast<char>(height >> 8 & 0xff), '\x80', '\0', '\0'};
  gif += bytes("\000\000\000\377\377\377");                      // global colour table
  gif += bytes(",\000\000\000\000\001\000\001\000\000");          // frame at (0, 0), 1 x 1
  gif += bytes("\002\002\104\001\000");                          // LZW: clear, 0, end
  gif += ";";
  return gif;
}

// Known before fuzzing (docs/fuzzing.md): a 35-byte GIF claiming 8192 x 8192 pixels, within
// kMaxMapCells, decoded to a 64-million-cell map and took about 0.7 GB while it did; stb_image
// fills what the frame does not cover with the background. The declared size is now checked
// against the file size before decoding.
TEST(FuzzRegression, GifDeclaringMorePixelsThanItsBytesCanHoldIsRefusedBeforeDecoding) {
  const std::string bomb = gifWithScreen(8192, 8192);
  ASSERT_EQ(bomb.size(), 35u);
  const std::string message = mapError([&] { decodeImage(bomb, "bomb.gif"); });
  EXPECT_TRUE(contains(message, {"bomb.gif: ", "GIF", "8192 x 8192", "35 bytes", "before decoding"})) << message;
  // Beyond the cell limit: refused for that reason, whatever the file size.
  EXPECT_TRUE(contains(mapError([] { decodeImage(gifWithScreen(8193, 8193), "huge.gif"); }),
                       {"huge.gif: ", "exceeds the limit"}));
  // A PNG header can lie the same way (gray.png, 69 bytes, relabelled 8192 x 8192).
  std::string png = kGrayPng;
  png.replace(16, 8, bytes("\000\000\040\000\000\000\040\000"));
  EXPECT_TRUE(contains(mapError([&] { decodeImage(png, "big.png"); }), {"big.png: ", "PNG", "8192 x 8192"}));
}

TEST(FuzzRegression, GifSizeCheckKeepsPlausibleFiles) {
  const GrayImage one = decodeImage(gifWithScreen(1, 1), "one.gif");
  EXPECT_EQ(one.width, 1);
  EXPECT_EQ(one.height, 1);
  EXPECT_EQ(one.pixels, std::vector<std::uint8_t>{0});  // colour 0, black
  // 35 bytes may hold up to 35 x 32768 pixels: a 1000 x 1000 screen is still decoded (the
  // frame's pixel, then the background).
  const GrayImage wide = decodeImage(gifWithScreen(1000, 1000), "wide.gif");
  EXPECT_EQ(wide.pixels.size(), 1000000u);
  EXPECT_EQ(wide.pixels[0], 0);
}

TEST(FuzzRegression, PgmHeadersWithHugeSizesAreRefusedBeforeAllocating) {
  EXPECT_TRUE(
      contains(mapError([] { parsePgm("P5 8193 8193 255\n", "big.pgm"); }), {"big.pgm: ", "exceeds the limit"}));
  EXPECT_TRUE(contains(mapError([] { parsePgm("P5 99999999999999999999999 1 255\n", "w.pgm"); }),
                       {"w.pgm: ", "width is larger than"}));
  EXPECT_TRUE(contains(mapError([] { parsePgm("P2 8192 8192 255\n0", "a.pgm"); }), {"a.pgm: ", "cannot hold"}));
  EXPECT_TRUE(contains(mapError([] { parsePgm("P5 8192 8192 65535\n\001\002", "b.pgm"); }),
                       {"b.pgm: ", "truncated PGM", "134217728"}));
  EXPECT_TRUE(contains(mapError([] { parsePgm("P5 1 1 65536\n\000", "m.pgm"); }), {"maxval is larger than 65535"}));
}

TEST(FuzzRegression, DeeplyNestedMapYamlIsAnError) {
  const auto never = [](const std::string&) -> std::string {
    ADD_FAILURE() << "no image should be read";
    return "";
  };
  for (const std::string& yaml : {std::string(100000, '['), std::string(100000, '{'), [] {
         std::string nested;
         for (int i = 0; i < 30000; ++i) nested += "{a: ";
         return nested;
       }()}) {
    const std::string message = mapError([&] { parseMapServerYaml(yaml, "/maps/deep.yaml", never); });
    EXPECT_TRUE(contains(message, {"/maps/deep.yaml: invalid YAML", "nested"})) << message.substr(0, 200);
    EXPECT_EQ(message.find("bad file"), std::string::npos) << message.substr(0, 200);
  }
}

TEST(FuzzRegression, MapYamlResolvesTheImageAndWrapsItsErrors) {
  const std::string yaml = "image: map.png\nresolution: 0.5\norigin: [1, 2, 0]\n";
  std::string asked;
  const OccupancyMap map = parseMapServerYaml(yaml, "/maps/lab.yaml", [&](const std::string& path) {
    asked = path;
    return kGrayPng;
  });
  EXPECT_EQ(asked, "/maps/map.png");
  EXPECT_EQ(map.width, 3);
  EXPECT_EQ(map.height, 2);
  EXPECT_EQ(map.cells, (std::vector<std::uint8_t>{kOccupiedValue, kUnknownValue, kFreeValue, kFreeValue,
                                                   kUnknownValue, kOccupiedValue}));

  const auto damaged_png = [](const std::string&) { return kPngIdatClaims1GiB; };
  const std::string message = mapError([&] { parseMapServerYaml(yaml, "/maps/lab.yaml", damaged_png); });
  EXPECT_TRUE(contains(message, {"/maps/lab.yaml: image: /maps/map.png: cannot decode image: truncated PNG"}))
      << message;
  const std::string nan_resolution = "image: m.pgm\nresolution: .nan\norigin: [0,0,0]\n";
  EXPECT_TRUE(contains(mapError([&] { parseMapServerYaml(nan_resolution, "/m.yaml"); }),
                       {"/m.yaml: key 'resolution' must be finite"}));
}

TEST(FuzzRegression, MatrixOddities) {
  EXPECT_TRUE(contains(mapError([] { parseMatrixText("\xEF\xBB\xBF", "bom.txt"); }), {"bom.txt: map has no cells"}));
  EXPECT_TRUE(contains(mapError([] { parseMatrixText(",0", "c.txt"); }), {"c.txt: line 1, column 1"}));
  EXPECT_TRUE(contains(mapError([] { parseMatrixText("0,\n", "c.txt"); }), {"c.txt: line 1, column 2"}));
  EXPECT_TRUE(contains(mapError([] { parseMatrixText(bytes("0\0001"), "nul.txt"); }), {"nul.txt: ", "byte 0x00"}));
  EXPECT_TRUE(contains(mapError([] { parseMatrixText("01\n0\n", "r.txt"); }), {"r.txt: line 2 has 1 cells"}));
  const OccupancyMap map = parseMatrixText("\xEF\xBB\xBF# c\n\r\n0 1,0\t1#x\n1100\r", "ok.txt");
  EXPECT_EQ(map.width, 4);
  EXPECT_EQ(map.height, 2);
}

// fuzz_parameters, read-back check (minimised to "lambda=0x4p-1074"): an exact hexadecimal
// subnormal was accepted, but its decimal form "1.976...e-323" was refused as out of range, so
// the value could not be written back (JSON report -> --params). Subnormals are now refused.
TEST(FuzzRegression, SubnormalParameterValuesAreRefusedInEverySpelling) {
  Parameters p;
  for (const char* value : {"0x4p-1074", "0x2147483648p-1074", "1.976262583365e-323", "1e-320", "-0x1p-1070"}) {
    EXPECT_THROW(setParameter(p, "lambda", value), ParameterError) << value;
  }
  setParameter(p, "lambda", "2.2250738585072014e-308");  // the smallest normal double
  EXPECT_EQ(p.lambda, 2.2250738585072014e-308);
  setParameter(p, "epsilon", "-0x0p0");
  EXPECT_EQ(p.epsilon, 0.0);
}

// Found while writing these tests (fuzz_parameters now checks it): strtoull skips leading spaces
// and negates, so seed=" -1" (a quoted value in --params, or --seed " -1") became 2^64 - 1.
TEST(FuzzRegression, ParameterEdgeValues) {
  Parameters p;
  setParameter(p, "alpha", "nan");  // a number, refused by validation
  EXPECT_TRUE(contains(validationError(p), {"alpha"}));
  p = Parameters{};
  setParameter(p, "seed", "18446744073709551615");
  EXPECT_EQ(p.seed, UINT64_MAX);
  EXPECT_EQ(validationError(p), "");
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{
           {"seed", "18446744073709551616"}, {"seed", "-1"}, {"seed", " -1"}, {"seed", "\t-5"}, {"seed", " 1"},
           {"seed", "+1"}, {"seed", ""},
           {"ants", "2147483648"}, {"ants", "-9223372036854775809"}, {"ants", "5 "}, {"q", "1e309"},
           {"alpha", ""}, {"allow_corner_cutting", "2"}, {"island_strategy", "Paper"}, {"", "1"},
           {std::string("ants\0", 5), "1"}}) {
    EXPECT_THROW(setParameter(p, key, value), ParameterError) << key << "=" << value;
  }
}

TEST(FuzzRegression, CliArgumentEdgeValues) {
  EXPECT_THROW(cli::parseSerial("9223372036854775808", "--start-cell"), std::invalid_argument);
  EXPECT_EQ(cli::parseSerial(" -9223372036854775808 ", "--start-cell"), INT64_MIN);
  EXPECT_THROW(cli::parseRowCol("2147483648,0", "--start"), std::invalid_argument);
  const Cell cell = cli::parseRowCol(" 12 , -3 ", "--start");
  EXPECT_EQ(cell.row, 12);
  EXPECT_EQ(cell.col, -3);
  for (const char* text : {"nan,0", "0,inf", "1e999,0", "0x1p99999,1", "1,2,3", ",", "1,", " ,1"}) {
    EXPECT_THROW(cli::parseXY(text, "--start-xy"), std::invalid_argument) << text;
  }
  EXPECT_THROW(cli::splitAssignment("=5", "--set"), std::invalid_argument);
  const auto kv = cli::splitAssignment(" a = b=c \n", "--set");
  EXPECT_EQ(kv.first, "a");
  EXPECT_EQ(kv.second, "b=c");
  EXPECT_EQ(cli::trim(" \t\r\n"), "");
}

}  // namespace
}  // namespace eaci
