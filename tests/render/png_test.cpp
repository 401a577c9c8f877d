#include "physltl/render/png.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace physltl::render {
namespace {

Image gradient(int width, int height) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = static_cast<std::uint8_t>(i * 7 % 251);
  return image;
}

TEST(Png, RoundTripsPixelsExactly) {
  const std::filesystem::path path = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / "round_trip.png";
  std::filesystem::create_directories(path.parent_path());
  const Image image = gradient(17, 9);
  write_png(image, path);
  const Image read = read_png(path);
  EXPECT_EQ(read.width, 17);
  EXPECT_EQ(read.height, 9);
  EXPECT_EQ(read.rgb, image.rgb);
}

TEST(Png, NamesTheFileItCannotWrite) {
  try {
    write_png(gradient(2, 2), "/nonexistent/folder/x.png");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/folder/x.png"), std::string::npos) << e.what();
  }
}

std::filesystem::path written(const std::string& name, const std::string& bytes) {
  const std::filesystem::path path = std::filesystem::path(PHYSLTL_TEST_OUTPUT_DIR) / name;
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// read_png's refusal of `path`: its message, which must name the file.
std::string refusal(const std::filesystem::path& path) {
  try {
    read_png(path);
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << path << " was read as a picture";
  return "";
}

// Pictures are read by content: a golden that is really another format (here a truncated Radiance HDR
// file, on which Debian's stb_image spins for ever) or a GIF is refused at once, naming the file.
TEST(Png, AnotherFormatNamedPngIsRefusedNamingTheFile) {
  EXPECT_NE(refusal(written("hdr.png", "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 2 +X 2\n\x02\x02\x00")).find("not a PNG"),
            std::string::npos);
  EXPECT_NE(refusal(written("gif.png", std::string("GIF89a\x01\x00\x01\x00\x00\x00\x00;", 14))).find("not a PNG"),
            std::string::npos);
}

std::uint32_t crc32_of(const std::uint8_t* bytes, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= bytes[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// A PNG whose header claims more pixels than any picture the program writes is refused before they are
// allocated.
TEST(Png, AHeaderClaimingAHugePictureIsRefusedBeforeItsPixels) {
  std::vector<std::uint8_t> bytes = encode_png(gradient(4, 4));
  // The IHDR chunk: length (4 bytes) at 8, "IHDR" at 12, width and height at 16 and 20, its CRC at 29.
  for (const std::size_t at : {16u, 20u}) {
    bytes[at] = 0x00, bytes[at + 1] = 0x01, bytes[at + 2] = 0x86, bytes[at + 3] = 0xA0;  // 100,000
  }
  const std::uint32_t crc = crc32_of(bytes.data() + 12, 17);
  for (int i = 0; i < 4; ++i) bytes[29 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(crc >> (24 - 8 * i));
  EXPECT_NE(refusal(written("huge.png", std::string(bytes.begin(), bytes.end()))).find("100000 x 100000"), std::string::npos);
}

}  // namespace
}  // namespace physltl::render
