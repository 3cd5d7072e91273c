// Map readers: map_server YAML + image, PGM (own parser), other images (stb_image), 0/1 text.
//
// Every reader validates its input completely and reports the first problem as a
// one-line MapLoadError naming the file; sizes are checked against kMaxMapCells and
// kMaxMapFileBytes before anything large is allocated.
#include "eaci/io/map_io.hpp"

#include <stb_image.h>
#include <yaml-cpp/depthguard.h>  // YAML::DeepRecursion (yaml-cpp 0.7)
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <system_error>
#include <utility>

#include "eaci/io/movingai_map.hpp"
#include "eaci/io/text.hpp"

namespace eaci {
namespace {

namespace fs = std::filesystem;

// A map_server YAML file is a handful of lines; anything this large is not one.
constexpr std::size_t kMaxYamlFileBytes = std::size_t{1} << 20;

// Numbers quoted in messages (thresholds, resolution) keep this many decimals at most.
constexpr int kMessageDecimals = 6;

// ------------------------------------------------------------------ errors

// Messages are one line (oneLine), whatever the file names contain.
[[noreturn]] void fail(const std::string& source, const std::string& reason) {
  throw MapLoadError(oneLine(source + ": " + reason));
}

[[noreturn]] void failOpen(const std::string& path, const std::string& reason) {
  throw MapLoadError(oneLine("cannot open " + path + ": " + reason));
}

// 'x' for a printable character, "byte 0x0a" for anything else.
std::string describeByte(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x20 && byte < 0x7f) return std::string("'") + c + "'";
  char hex[16];
  std::snprintf(hex, sizeof hex, "byte 0x%02x", byte);
  return hex;
}

std::string errnoMessage(int error) { return std::error_code(error, std::generic_category()).message(); }

// ------------------------------------------------------------------ files

// Refuses directories, FIFOs and devices up front: opening a FIFO could block and a
// device such as /dev/zero never ends.
void requireRegularFile(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (error) failOpen(path, error.message());
  if (fs::is_directory(status)) failOpen(path, errnoMessage(EISDIR));
  if (!fs::is_regular_file(status)) failOpen(path, "not a regular file");
}

std::string readFileBytes(const std::string& path, std::size_t max_bytes) {
  requireRegularFile(path);
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) failOpen(path, errnoMessage(errno));

  std::string bytes;
  char buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) {
    if (got > max_bytes - bytes.size()) {
      fail(path, "file is larger than the limit of " + std::to_string(max_bytes) + " bytes");
    }
    bytes.append(buffer, got);
  }
  if (std::ferror(file.get())) failOpen(path, "read error");
  return bytes;
}

// The file name ends in one of `extensions` (lower case, with the dot), in any case.
bool hasExtension(const std::string& path, std::initializer_list<const char*> extensions) {
  std::string extension = fs::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* e : extensions)
    if (extension == e) return true;
  return false;
}

// ------------------------------------------------------------------ image sizes

// width * height, refused (without overflowing) when it exceeds kMaxMapCells.
std::size_t checkedCellCount(std::uint64_t width, std::uint64_t height, const std::string& source) {
  if (width == 0 || height == 0) {
    fail(source, "image of " + std::to_string(width) + " x " + std::to_string(height) + " pixels has no cells");
  }
  if (width > kMaxMapCells / height) {
    fail(source, "image of " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels exceeds the limit of " + std::to_string(kMaxMapCells) + " cells");
  }
  return static_cast<std::size_t>(width * height);
}

// ------------------------------------------------------------------ PGM

bool isPgmWhitespace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// 0..maxval -> 0..255, rounded to nearest.
std::uint8_t scaleToByte(std::uint32_t value, std::uint32_t maxval) {
  return static_cast<std::uint8_t>((value * 255u + maxval / 2u) / maxval);
}

struct PgmHeader {
  bool binary = true;  // P5; false for P2
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t maxval = 0;
};

// Netpbm PGM (https://netpbm.sourceforge.net/doc/pgm.html): magic, width, height, maxval
// separated by whitespace and '#' comments, then one whitespace character, then the raster.
class PgmParser {
 public:
  PgmParser(const std::string& bytes, const std::string& source) : bytes_(bytes), source_(source) {}

  // The image; `header`, when given, receives the header (maxval: the scale of the raster).
  GrayImage parse(PgmHeader* header_out = nullptr) {
    const PgmHeader header = readHeader();
    if (header_out != nullptr) *header_out = header;
    const std::size_t cells = checkedCellCount(header.width, header.height, source_);
    GrayImage image;
    image.width = static_cast<int>(header.width);
    image.height = static_cast<int>(header.height);
    image.pixels = header.binary ? readBinaryRaster(cells, header.maxval) : readAsciiRaster(cells, header.maxval);
    return image;
  }

 private:
  PgmHeader readHeader() {
    PgmHeader header;
    header.binary = readMagic();
    header.width = static_cast<std::uint32_t>(readHeaderNumber("width", kMaxMapCells));
    header.height = static_cast<std::uint32_t>(readHeaderNumber("height", kMaxMapCells));
    header.maxval = static_cast<std::uint32_t>(readHeaderNumber("maxval", 65535));
    if (header.width == 0 || header.height == 0) {
      fail(source_, "PGM size " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                        " has no cells");
    }
    if (header.maxval == 0) fail(source_, "PGM maxval must be 1..65535, got 0");
    skipWhitespaceAfterMaxval();
    return header;
  }

  // True for P5, false for P2.
  bool readMagic() {
    if (bytes_.size() < 2 || bytes_[0] != 'P' || (bytes_[1] != '5' && bytes_[1] != '2')) {
      fail(source_, "not a PGM file: the magic number must be P5 or P2");
    }
    pos_ = 2;
    return bytes_[1] == '5';
  }

  // Whitespace and comments before a header number; at least one separator is required
  // so that "P52" or "12#" followed by digits cannot run two tokens together.
  void skipHeaderSeparators(const std::string& next_field) {
    const std::size_t start = pos_;
    while (pos_ < bytes_.size()) {
      if (isPgmWhitespace(bytes_[pos_])) {
        ++pos_;
      } else if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r') ++pos_;
      } else {
        break;
      }
    }
    if (pos_ == bytes_.size()) fail(source_, "truncated PGM header: missing " + next_field);
    if (pos_ == start) {
      fail(source_, "PGM header: expected whitespace before " + next_field + ", found " + describeByte(bytes_[pos_]));
    }
  }

  std::uint64_t readHeaderNumber(const std::string& field, std::uint64_t max_value) {
    skipHeaderSeparators(field);
    if (!isDigit(bytes_[pos_])) {
      fail(source_, "PGM header: expected " + field + " (a non-negative integer), found " + describeByte(bytes_[pos_]));
    }
    std::uint64_t value = 0;
    for (; pos_ < bytes_.size() && isDigit(bytes_[pos_]); ++pos_) {
      value = value * 10 + static_cast<std::uint64_t>(bytes_[pos_] - '0');
      if (value > max_value) fail(source_, "PGM " + field + " is larger than " + std::to_string(max_value));
    }
    return value;
  }

  void skipWhitespaceAfterMaxval() {
    if (pos_ == bytes_.size()) fail(source_, "truncated PGM: missing whitespace and pixel data after maxval");
    if (!isPgmWhitespace(bytes_[pos_])) {
      fail(source_, "PGM header: expected whitespace after maxval, found " + describeByte(bytes_[pos_]));
    }
    ++pos_;
  }

  std::vector<std::uint8_t> readBinaryRaster(std::size_t cells, std::uint32_t maxval) {
    const std::size_t bytes_per_pixel = maxval > 255 ? 2 : 1;
    const std::size_t needed = cells * bytes_per_pixel;
    const std::size_t available = bytes_.size() - pos_;
    if (available < needed) {
      fail(source_, "truncated PGM: expected " + std::to_string(needed) + " bytes of pixel data, found " +
                        std::to_string(available));
    }
    std::vector<std::uint8_t> pixels(cells);
    const auto* raster = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    for (std::size_t i = 0; i < cells; ++i) {
      const std::uint32_t value = bytes_per_pixel == 1
                                      ? raster[i]
                                      : (static_cast<std::uint32_t>(raster[2 * i]) << 8) | raster[2 * i + 1];
      if (value > maxval) {
        fail(source_, "PGM pixel " + std::to_string(i) + " has value " + std::to_string(value) + " above maxval " +
                          std::to_string(maxval));
      }
      pixels[i] = scaleToByte(value, maxval);
    }
    return pixels;
  }

  std::vector<std::uint8_t> readAsciiRaster(std::size_t cells, std::uint32_t maxval) {
    // Each value takes at least one digit and one separator: refuse short files before allocating.
    const std::size_t available = bytes_.size() - pos_;
    if (available < 2 * cells - 1) {
      fail(source_, "truncated PGM: " + std::to_string(available) + " bytes cannot hold " + std::to_string(cells) +
                        " pixel values");
    }
    std::vector<std::uint8_t> pixels(cells);
    for (std::size_t i = 0; i < cells; ++i) pixels[i] = scaleToByte(readAsciiValue(i, cells, maxval), maxval);
    return pixels;
  }

  std::uint32_t readAsciiValue(std::size_t index, std::size_t cells, std::uint32_t maxval) {
    while (pos_ < bytes_.size() && isPgmWhitespace(bytes_[pos_])) ++pos_;
    if (pos_ == bytes_.size()) {
      fail(source_, "truncated PGM: found " + std::to_string(index) + " of " + std::to_string(cells) + " pixel values");
    }
    if (!isDigit(bytes_[pos_])) {
      fail(source_, "PGM pixel " + std::to_string(index) + ": expected a number, found " + describeByte(bytes_[pos_]));
    }
    std::uint32_t value = 0;
    for (; pos_ < bytes_.size() && isDigit(bytes_[pos_]); ++pos_) {
      value = value * 10 + static_cast<std::uint32_t>(bytes_[pos_] - '0');
      if (value > maxval) {
        fail(source_, "PGM pixel " + std::to_string(index) + " has a value above maxval " + std::to_string(maxval));
      }
    }
    if (pos_ < bytes_.size() && !isPgmWhitespace(bytes_[pos_])) {
      fail(source_, "PGM pixel " + std::to_string(index) + ": unexpected " + describeByte(bytes_[pos_]) +
                        " after the number");
    }
    return value;
  }

  const std::string& bytes_;
  const std::string& source_;
  std::size_t pos_ = 0;
};

// ------------------------------------------------------------------ other images (stb_image)

bool startsWith(const std::string& bytes, const char* prefix, std::size_t length) {
  return bytes.size() >= length && bytes.compare(0, length, prefix, length) == 0;
}

// Only formats with a real signature go to stb_image: its TGA reader, tried last, would
// otherwise accept almost any bytes as an image. PPM and JPEG are left out on purpose: the
// PNM and JPEG readers of the packaged stb_image (2022-09) crash on damaged files, and a
// lossy JPEG makes a poor occupancy map anyway.
bool hasStbImageSignature(const std::string& bytes) {
  return startsWith(bytes, "\x89PNG\r\n\x1a\n", 8) || startsWith(bytes, "BM", 2) || startsWith(bytes, "GIF8", 4);
}

std::uint32_t byteAt(const std::string& bytes, std::size_t i) {
  return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]));
}

// Every PNG chunk up to IEND must fit in the file. stb_image reserves an IDAT chunk's declared
// length (up to 2 GiB) before it reads the data, so a 70-byte file could claim 1 GiB (found by
// fuzz_image); files that fail here would fail in stb_image too, only after that allocation.
// An empty first IDAT chunk is refused too: stb_image copies it to a null buffer (undefined
// behaviour, found by fuzz_map_yaml).
void checkPngChunkLengths(const std::string& bytes, const std::string& source) {
  bool have_image_data = false;
  std::size_t pos = 8;  // after the signature
  while (bytes.size() - pos >= 8) {
    const std::uint32_t length =
        byteAt(bytes, pos) << 24 | byteAt(bytes, pos + 1) << 16 | byteAt(bytes, pos + 2) << 8 | byteAt(bytes, pos + 3);
    const std::string type = bytes.substr(pos + 4, 4);
    const std::size_t available = bytes.size() - pos - 8;
    if (length > available) {
      const bool named =
          std::all_of(type.begin(), type.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
      fail(source, "cannot decode image: truncated PNG: chunk " + (named ? type + " " : std::string()) + "at byte " +
                       std::to_string(pos) + " declares " + std::to_string(length) + " bytes of data, but only " +
                       std::to_string(available) + " follow");
    }
    if (type == "IEND") return;
    if (type == "IDAT") {
      if (length == 0 && !have_image_data) fail(source, "cannot decode image: PNG with an empty first IDAT chunk");
      have_image_data = true;
    }
    pos += 8 + std::size_t{length} + std::min<std::size_t>(4, available - length);  // + CRC
  }
}

// Uncompressed BMP rows must all be in the file. stb_image's BMP reader reads zeros past the
// end of the data, so a 149-byte file declaring 1048578 x 46 pixels decoded to a 48-million-cell
// map (found by fuzz_image). The last row may lack its padding. The pixel data starts at the
// file header's offset whenever stb_image accepts the file (12-byte or 40+ byte info header).
void checkBmpPixelData(const std::string& bytes, int width, int height, const std::string& source) {
  const auto le16 = [&bytes](std::size_t i) { return byteAt(bytes, i) | byteAt(bytes, i + 1) << 8; };
  const auto le32 = [&le16](std::size_t i) { return le16(i) | le16(i + 2) << 16; };
  if (bytes.size() < 18) fail(source, "cannot decode image: truncated BMP header");
  const std::size_t bpp_at = le32(14) == 12 ? 24 : 28;
  if (bytes.size() < bpp_at + 2) fail(source, "cannot decode image: truncated BMP header");
  const std::uint64_t offset = le32(10);
  const std::uint64_t bits_per_pixel = le16(bpp_at);
  const std::uint64_t row_bits = static_cast<std::uint64_t>(width) * bits_per_pixel;
  const std::uint64_t stride = (row_bits + 31) / 32 * 4;
  const std::uint64_t needed = offset + stride * (static_cast<std::uint64_t>(height) - 1) + (row_bits + 7) / 8;
  if (bytes.size() < needed) {
    fail(source, "cannot decode image: truncated BMP: " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels of " + std::to_string(bits_per_pixel) + " bits from byte " + std::to_string(offset) +
                     " need " + std::to_string(needed) + " bytes, the file has " + std::to_string(bytes.size()));
  }
}

// The most pixels a complete file of each compressed format can hold per byte of the file.
// PNG: deflate expands at most 1032-fold and a pixel takes at least one bit (8 x 1032).
// GIF: an LZW code takes at least one bit and stands for at most 4096 pixels (8 x 4096).
// stb_image allocates the declared size before it decodes, and fills what the data leave out
// with the background colour (GIF), so a 35-byte GIF declaring 8192 x 8192 pixels decoded to
// a 64-million-cell map using about 0.7 GB; such sizes are refused from the header alone.
// Uncompressed BMP is checked exactly by checkBmpPixelData.
constexpr std::uint64_t kMaxPngPixelsPerByte = 8 * 1032;
constexpr std::uint64_t kMaxGifPixelsPerByte = 8 * 4096;

void checkDeclaredSizeIsPlausible(const std::string& bytes, std::size_t cells, int width, int height,
                                  const std::string& source) {
  const bool png = startsWith(bytes, "\x89PNG\r\n\x1a\n", 8), gif = startsWith(bytes, "GIF8", 4);
  if (!png && !gif) return;
  const std::uint64_t per_byte = png ? kMaxPngPixelsPerByte : kMaxGifPixelsPerByte;
  if (cells <= bytes.size() * per_byte) return;  // no overflow: the file has at most INT_MAX bytes
  fail(source, std::string("cannot decode image: the ") + (png ? "PNG" : "GIF") + " header declares " +
                   std::to_string(width) + " x " + std::to_string(height) + " pixels, more than a file of " +
                   std::to_string(bytes.size()) + " bytes can hold (at most " + std::to_string(per_byte) +
                   " pixels per byte); refused before decoding");
}

std::string stbFailureReason() {
  const char* reason = stbi_failure_reason();
  return std::string("cannot decode image: ") + (reason != nullptr ? reason : "unknown error");
}

// An image decoded by stb_image: `channels` bytes per pixel, row 0 = top.
struct StbPixels {
  std::unique_ptr<stbi_uc, void (*)(void*)> data{nullptr, &stbi_image_free};
  int width = 0;
  int height = 0;
  int channels = 0;
  std::size_t cells = 0;
};

// Decodes PNG, BMP or GIF with stb_image after the checks above, converted to
// `desired_channels` bytes per pixel (0: as many as the file has).
StbPixels decodeWithStbImage(const std::string& bytes, const std::string& source, int desired_channels) {
  if (!hasStbImageSignature(bytes)) {
    fail(source, "unrecognised image format (supported: PGM P2/P5, PNG, BMP, GIF)");
  }
  if (bytes.size() > static_cast<std::size_t>(INT_MAX)) fail(source, "image file too large");
  if (startsWith(bytes, "\x89PNG\r\n\x1a\n", 8)) checkPngChunkLengths(bytes, source);
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int length = static_cast<int>(bytes.size());

  StbPixels image;
  if (!stbi_info_from_memory(data, length, &image.width, &image.height, &image.channels)) {
    fail(source, stbFailureReason());
  }
  if (image.width <= 0 || image.height <= 0) fail(source, "image has no pixels");
  image.cells = checkedCellCount(static_cast<std::uint64_t>(image.width), static_cast<std::uint64_t>(image.height),
                                 source);
  checkDeclaredSizeIsPlausible(bytes, image.cells, image.width, image.height, source);
  if (startsWith(bytes, "BM", 2)) checkBmpPixelData(bytes, image.width, image.height, source);

  stbi_set_flip_vertically_on_load_thread(0);  // row 0 must stay the top row
  int width = 0, height = 0, file_channels = 0;
  image.data.reset(stbi_load_from_memory(data, length, &width, &height, &file_channels, desired_channels));
  if (!image.data) fail(source, stbFailureReason());
  if (static_cast<std::size_t>(width) * static_cast<std::size_t>(height) != image.cells) {
    fail(source, "image size changed while decoding");
  }
  image.channels = desired_channels != 0 ? desired_channels : file_channels;
  return image;
}

// Colour images become grey with stb_image's luma weights (map_server takes the plain
// mean of the channels; the difference only matters for coloured pixels near a threshold).
// An alpha channel is dropped.
GrayImage decodeGreyWithStbImage(const std::string& bytes, const std::string& source) {
  const StbPixels decoded = decodeWithStbImage(bytes, source, 1);
  GrayImage image;
  image.width = decoded.width;
  image.height = decoded.height;
  image.pixels.assign(decoded.data.get(), decoded.data.get() + decoded.cells);
  return image;
}

// map_server's raw reading of one pixel (image_loader.cpp): the mean of its colour channels
// (an alpha channel not counted), 255 minus that with negate, truncated to a byte.
std::uint8_t rawPixelValue(const stbi_uc* pixel, int channels, bool negate) {
  const int colours = channels == 2 || channels == 4 ? channels - 1 : channels;
  int sum = 0;
  for (int k = 0; k < colours; ++k) sum += pixel[k];
  double mean = sum / static_cast<double>(colours);
  if (negate) mean = 255.0 - mean;
  return static_cast<std::uint8_t>(mean);
}

// ------------------------------------------------------------------ 0/1 text matrix

// One line of a matrix file -> its cells (empty for blank and comment lines).
// Cells are '0' / '1'; spaces, tabs and CRs separate them or may be left out; a comma must
// sit between two cells; '#' starts a comment.
class MatrixLineParser {
 public:
  MatrixLineParser(const std::string& source, std::size_t line_number) : source_(source), line_(line_number) {}

  std::vector<std::uint8_t> parse(const std::string& line) {
    std::vector<std::uint8_t> row;
    bool last_was_comma = false;
    std::size_t comma_column = 0;
    for (std::size_t i = 0; i < line.size() && line[i] != '#'; ++i) {
      const char c = line[i];
      const std::size_t column = i + 1;
      if (c == ' ' || c == '\t' || c == '\r') continue;
      if (c == ',') {
        if (row.empty() || last_was_comma) failAt(column, "',' without a cell before it");
        last_was_comma = true;
        comma_column = column;
      } else if (c == '0' || c == '1') {
        if (row.size() == kMaxMapCells) failAt(column, "row longer than " + std::to_string(kMaxMapCells) + " cells");
        row.push_back(c == '0' ? kFreeValue : kOccupiedValue);
        last_was_comma = false;
      } else {
        failAt(column, "unexpected character " + describeByte(c) +
                           " (cells must be 0 or 1, separated by spaces, tabs or commas)");
      }
    }
    if (last_was_comma) failAt(comma_column, "',' without a cell after it");
    return row;
  }

 private:
  [[noreturn]] void failAt(std::size_t column, const std::string& reason) const {
    fail(source_, "line " + std::to_string(line_) + ", column " + std::to_string(column) + ": " + reason);
  }

  const std::string& source_;
  std::size_t line_;
};

// Appends rows while checking that they all have the same length and stay within kMaxMapCells.
class MatrixBuilder {
 public:
  explicit MatrixBuilder(const std::string& source) : source_(source) {}

  void addRow(const std::vector<std::uint8_t>& row, std::size_t line_number) {
    if (rows_ == 0) {
      width_ = row.size();
      first_line_ = line_number;
    } else if (row.size() != width_) {
      fail(source_, "line " + std::to_string(line_number) + " has " + std::to_string(row.size()) +
                        " cells, but line " + std::to_string(first_line_) + " has " + std::to_string(width_));
    }
    if (rows_ + 1 > kMaxMapCells / width_) {
      fail(source_, "map exceeds the limit of " + std::to_string(kMaxMapCells) + " cells");
    }
    cells_.insert(cells_.end(), row.begin(), row.end());
    ++rows_;
  }

  OccupancyMap build() {
    if (rows_ == 0) fail(source_, "map has no cells");
    OccupancyMap map;
    map.width = static_cast<int>(width_);
    map.height = static_cast<int>(rows_);
    map.resolution = 1.0;
    map.cells = std::move(cells_);
    return map;
  }

 private:
  const std::string& source_;
  std::vector<std::uint8_t> cells_;
  std::size_t width_ = 0;
  std::size_t rows_ = 0;
  std::size_t first_line_ = 0;
};

// ------------------------------------------------------------------ map_server YAML

struct MapServerMetadata {
  std::string image_path;  // resolved against the YAML file's directory
  double resolution = 0.0;
  std::array<double, 3> origin{};  // x, y, yaw
  MapServerThresholds thresholds;
  MapServerMode mode = MapServerMode::kTrinary;
};

// Wraps yaml-cpp lookups and conversions so that every error names the file and the key.
class YamlMapReader {
 public:
  YamlMapReader(const std::string& yaml_path, YAML::Node root) : path_(yaml_path), root_(std::move(root)) {}

  MapServerMetadata read() const {
    if (!root_.IsMap()) fail(path_, "expected a YAML mapping with the keys image, resolution and origin");
    MapServerMetadata metadata;
    metadata.image_path = readImagePath();
    metadata.resolution = readPositiveNumber("resolution");
    metadata.origin = readOrigin();
    metadata.thresholds.negate = readNegate();
    metadata.thresholds.occupied_thresh = readThreshold("occupied_thresh", 0.65);
    metadata.thresholds.free_thresh = readThreshold("free_thresh", 0.196);
    if (!(metadata.thresholds.free_thresh < metadata.thresholds.occupied_thresh)) {
      fail(path_, "free_thresh (" + formatNumber(metadata.thresholds.free_thresh, kMessageDecimals) +
                      ") must be smaller than occupied_thresh (" +
                      formatNumber(metadata.thresholds.occupied_thresh, kMessageDecimals) + ")");
    }
    metadata.mode = readMode();
    return metadata;
  }

 private:
  YAML::Node optionalKey(const std::string& key) const { return root_[key]; }

  YAML::Node requiredKey(const std::string& key) const {
    YAML::Node node = root_[key];
    if (!node.IsDefined()) fail(path_, "missing key '" + key + "'");
    return node;
  }

  [[noreturn]] void failKey(const std::string& key, const std::string& reason) const {
    fail(path_, "key '" + key + "' " + reason);
  }

  std::string readScalar(const YAML::Node& node, const std::string& key, const std::string& expected) const {
    if (!node.IsScalar()) failKey(key, "must be " + expected);
    return node.Scalar();
  }

  double readNumber(const YAML::Node& node, const std::string& key) const {
    const std::string text = readScalar(node, key, "a number");
    double value = 0.0;
    if (!YAML::convert<double>::decode(node, value)) failKey(key, "must be a number, got '" + text + "'");
    if (!std::isfinite(value)) failKey(key, "must be finite, got '" + text + "'");
    return value;
  }

  double readPositiveNumber(const std::string& key) const {
    const double value = readNumber(requiredKey(key), key);
    if (!(value > 0.0)) failKey(key, "must be positive, got " + formatNumber(value, kMessageDecimals));
    return value;
  }

  double readThreshold(const std::string& key, double default_value) const {
    const YAML::Node node = optionalKey(key);
    if (!node.IsDefined()) return default_value;
    const double value = readNumber(node, key);
    if (value < 0.0 || value > 1.0) failKey(key, "must be between 0 and 1, got " + formatNumber(value, kMessageDecimals));
    return value;
  }

  std::array<double, 3> readOrigin() const {
    const YAML::Node node = requiredKey("origin");
    if (!node.IsSequence() || node.size() != 3) failKey("origin", "must be a list of 3 numbers [x, y, yaw]");
    std::array<double, 3> origin{};
    for (std::size_t i = 0; i < origin.size(); ++i) origin[i] = readNumber(node[i], "origin");
    return origin;
  }

  // map_server reads an int (0 / 1); nav2 also takes true / false.
  bool readNegate() const {
    const YAML::Node node = optionalKey("negate");
    if (!node.IsDefined()) return false;
    const std::string text = readScalar(node, "negate", "0, 1, true or false");
    int as_int = 0;
    if (YAML::convert<int>::decode(node, as_int) && (as_int == 0 || as_int == 1)) return as_int == 1;
    bool as_bool = false;
    if (YAML::convert<bool>::decode(node, as_bool)) return as_bool;
    failKey("negate", "must be 0, 1, true or false, got '" + text + "'");
  }

  // map_server's modes: trinary (also when the key is absent) and raw; scale is refused.
  MapServerMode readMode() const {
    const YAML::Node node = optionalKey("mode");
    if (!node.IsDefined()) return MapServerMode::kTrinary;
    const std::string mode = readScalar(node, "mode", "trinary or raw");
    if (mode == "trinary") return MapServerMode::kTrinary;
    if (mode == "raw") return MapServerMode::kRaw;
    if (mode == "scale") {
      failKey("mode", "is 'scale', which is not supported: map_server would publish occupancies 1..99 between "
                      "the thresholds, which this planner does not read; use trinary, or raw with costmap_2d costs");
    }
    failKey("mode", "must be trinary or raw (map_server also knows scale), got '" + mode + "'");
  }

  std::string readImagePath() const {
    const std::string image = readScalar(requiredKey("image"), "image", "a file name");
    if (image.empty()) failKey("image", "must not be empty");
    const fs::path image_path(image);
    if (image_path.is_absolute()) return image;
    return (fs::path(path_).parent_path() / image_path).string();
  }

  const std::string& path_;
  YAML::Node root_;
};

YAML::Node parseYamlDocument(const std::string& text, const std::string& yaml_path) {
  try {
    return YAML::Load(text);
  } catch (const YAML::DeepRecursion&) {
    // yaml-cpp 0.7 reports its nesting limit as "error at line 1, column 1: bad file".
    fail(yaml_path, "invalid YAML: nested more deeply than the YAML reader allows");
  } catch (const YAML::Exception& error) {
    fail(yaml_path, std::string("invalid YAML: ") + error.what());
  }
}

MapServerMetadata parseMapServerMetadata(const std::string& text, const std::string& yaml_path) {
  const YAML::Node root = parseYamlDocument(text, yaml_path);
  try {
    return YamlMapReader(yaml_path, root).read();
  } catch (const YAML::Exception& error) {
    fail(yaml_path, std::string("invalid map description: ") + error.what());
  }
}

// The image of a map_server map, decoded as its mode asks: grey levels to threshold (trinary),
// or raw pixel values (raw).
GrayImage loadImageFile(const std::string& image_path, const std::string& yaml_path, const MapServerMetadata& metadata,
                        const ImageFileReader& read_image) {
  try {
    const std::string bytes = read_image ? read_image(image_path) : readFileBytes(image_path, kMaxMapFileBytes);
    return metadata.mode == MapServerMode::kRaw ? decodeRawImage(bytes, metadata.thresholds.negate, image_path)
                                                : decodeImage(bytes, image_path);
  } catch (const MapLoadError& error) {
    fail(yaml_path, std::string("image: ") + error.what());
  }
}

}  // namespace

// ------------------------------------------------------------------ public interface

GrayImage parsePgm(const std::string& bytes, const std::string& source_name) {
  return PgmParser(bytes, source_name).parse();
}

GrayImage decodeImage(const std::string& bytes, const std::string& source_name) {
  const bool is_pgm = bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5');
  return is_pgm ? parsePgm(bytes, source_name) : decodeGreyWithStbImage(bytes, source_name);
}

GrayImage decodeRawImage(const std::string& bytes, bool negate, const std::string& source_name) {
  static const char* kSupported = "raw mode reads 8-bit images only: PGM with maxval 255, or PNG of 8 bits per channel "
                                  "(grey or colour, no palette), whose pixel values are the cells' values";
  if (bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '2' || bytes[1] == '5')) {
    PgmHeader header;
    GrayImage image = PgmParser(bytes, source_name).parse(&header);
    if (header.maxval != 255) fail(source_name, "PGM maxval is " + std::to_string(header.maxval) + ": " + kSupported);
    if (negate) {
      for (std::uint8_t& value : image.pixels) value = static_cast<std::uint8_t>(255 - value);
    }
    return image;
  }
  if (!startsWith(bytes, "\x89PNG\r\n\x1a\n", 8)) fail(source_name, std::string("not a PGM or PNG image: ") + kSupported);
  // IHDR, the first chunk: width, height, bit depth (byte 24), colour type (byte 25; 3 = palette).
  if (bytes.size() < 26 || bytes.compare(12, 4, "IHDR") != 0) fail(source_name, "cannot decode image: no PNG IHDR chunk");
  const std::uint32_t bit_depth = byteAt(bytes, 24), colour_type = byteAt(bytes, 25);
  if (bit_depth != 8) fail(source_name, "PNG of " + std::to_string(bit_depth) + " bits per channel: " + kSupported);
  if (colour_type == 3) fail(source_name, std::string("PNG with a palette: ") + kSupported);
  const StbPixels decoded = decodeWithStbImage(bytes, source_name, 0);
  GrayImage image;
  image.width = decoded.width;
  image.height = decoded.height;
  image.pixels.resize(decoded.cells);
  const auto channels = static_cast<std::size_t>(decoded.channels);
  for (std::size_t i = 0; i < decoded.cells; ++i)
    image.pixels[i] = rawPixelValue(decoded.data.get() + i * channels, decoded.channels, negate);
  return image;
}

std::vector<std::uint8_t> thresholdImage(const GrayImage& image, const MapServerThresholds& thresholds) {
  std::vector<std::uint8_t> cells(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), cells.begin(), [&thresholds](std::uint8_t value) {
    const double occupancy = thresholds.negate ? value / 255.0 : (255 - value) / 255.0;
    if (occupancy > thresholds.occupied_thresh) return kOccupiedValue;
    if (occupancy < thresholds.free_thresh) return kFreeValue;
    return kUnknownValue;
  });
  return cells;
}

OccupancyMap loadMapServerYaml(const std::string& yaml_path) {
  return parseMapServerYaml(readFileBytes(yaml_path, kMaxYamlFileBytes), yaml_path);
}

OccupancyMap parseMapServerYaml(const std::string& yaml_text, const std::string& yaml_path,
                                const ImageFileReader& read_image) {
  const MapServerMetadata metadata = parseMapServerMetadata(yaml_text, yaml_path);
  GrayImage image = loadImageFile(metadata.image_path, yaml_path, metadata, read_image);

  OccupancyMap map;
  map.width = image.width;
  map.height = image.height;
  map.resolution = metadata.resolution;
  map.origin = {metadata.origin[0], metadata.origin[1]};
  map.origin_yaw = metadata.origin[2];
  if (metadata.mode == MapServerMode::kRaw) {
    map.cells = std::move(image.pixels);
    map.values = CellValues::kCostmapCosts;
  } else {
    map.cells = thresholdImage(image, metadata.thresholds);
  }
  return map;
}

OccupancyMap parseMatrixText(const std::string& text, const std::string& source_name) {
  static const std::string kUtf8Bom = "\xEF\xBB\xBF";
  MatrixBuilder builder(source_name);
  std::size_t begin = text.compare(0, kUtf8Bom.size(), kUtf8Bom) == 0 ? kUtf8Bom.size() : 0;
  for (std::size_t line_number = 1; begin <= text.size(); ++line_number) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    const std::vector<std::uint8_t> row =
        MatrixLineParser(source_name, line_number).parse(text.substr(begin, end - begin));
    if (!row.empty()) builder.addRow(row, line_number);
    begin = end + 1;
  }
  return builder.build();
}

OccupancyMap loadMatrixText(const std::string& path) {
  return parseMatrixText(readFileBytes(path, kMaxMapFileBytes), path);
}

OccupancyMap loadMovingAiMap(const std::string& path) {
  return parseMovingAiMap(readFileBytes(path, kMaxMapFileBytes), path);
}

OccupancyMap loadMap(const std::string& path) {
  if (hasExtension(path, {".yaml", ".yml"})) return loadMapServerYaml(path);
  if (hasExtension(path, {".map"})) return loadMovingAiMap(path);
  return loadMatrixText(path);
}

}  // namespace eaci
