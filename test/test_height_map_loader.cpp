// Height map files into grids (config::loadHeightMap): 16-bit PNG (written here with libpng's
// own writer), PGM and CSV round trips, the image layout (top row = +y edge), the 8-bit warning
// and smoothing, and errors that name the file, the key, the line or the pixel, and the limit.

#include <gtest/gtest.h>
#include <png.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "expect_invalid_argument.hpp"
#include "spherical_robots/config/height_map_files.hpp"
#include "spherical_robots/config/height_map_loader.hpp"
#include "spherical_robots/config/terrain_config.hpp"
#include "spherical_robots/terrain/height_map_surface.hpp"

namespace {

namespace config = spherical_robots::config;

// Large enough for the 8-bit smoothing's reach (8 samples at sigma 2).
constexpr int kWidth = 12;   // columns: x
constexpr int kHeight = 9;   // rows: y, top row first

/// A file in the test's temp directory, removed when it goes.
class TempFile {
 public:
  explicit TempFile(const std::string& name)
      : path_(::testing::TempDir() + std::to_string(::getpid()) + "_" + name) {}
  ~TempFile() { std::remove(path_.c_str()); }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::string& path() const { return path_; }
  /// The name relative to the temp directory, as a YAML beside it names it.
  std::string name() const { return path_.substr(path_.find_last_of('/') + 1); }
  void write(const std::string& bytes) const { std::ofstream(path_, std::ios::binary) << bytes; }

 private:
  std::string path_;
};

/// Distinct levels with 0 and the maximum in them: level(row, column).
unsigned level(int row, int column, unsigned max_level) {
  if (row == 0 && column == 0) return max_level;
  return (static_cast<unsigned>(row * 9973 + column * 31337) + 1u) % max_level;
}

void writePng(const std::string& path, bool sixteen_bit) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = kWidth;
  image.height = kHeight;
  image.format = sixteen_bit ? PNG_FORMAT_LINEAR_Y : PNG_FORMAT_GRAY;
  std::vector<std::uint16_t> wide;
  std::vector<std::uint8_t> narrow;
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) {
      wide.push_back(static_cast<std::uint16_t>(level(r, c, 65535)));
      narrow.push_back(static_cast<std::uint8_t>(level(r, c, 255)));
    }
  }
  const void* buffer = sixteen_bit ? static_cast<const void*>(wide.data()) : narrow.data();
  ASSERT_NE(png_image_write_to_file(&image, path.c_str(), 0, buffer, 0, nullptr), 0) << image.message;
}

std::string description(const std::string& data_key, const std::string& file,
                        const std::string& extra = "min_height: -0.5\nmax_height: 1.5\n") {
  return data_key + ": " + file + "\nresolution: 0.25\norigin: [1.0, -2.0, 0.0]\n" + extra;
}

/// The height the description gives a grey level: min_height + range * level / max_level.
double heightOf(unsigned grey, unsigned max_level) { return -0.5 + 2.0 * grey / max_level; }

void expectImageLayout(const config::LoadedHeightMap& map, unsigned max_level) {
  const auto& grid = map.grid;
  ASSERT_EQ(grid.heights.rows(), kWidth);
  ASSERT_EQ(grid.heights.cols(), kHeight);
  EXPECT_EQ(grid.spacing, 0.25);
  // map_server's origin is the bottom-left pixel's outer corner; a sample sits at its centre.
  EXPECT_EQ(grid.first_sample, Eigen::Vector2d(1.125, -1.875));
  for (int i = 0; i < kWidth; ++i) {
    for (int j = 0; j < kHeight; ++j) {
      // x grows with the column, y upwards: the image's bottom row is j = 0.
      EXPECT_NEAR(grid.heights(i, j), heightOf(level(kHeight - 1 - j, i, max_level), max_level),
                  1e-15)
          << i << ", " << j;
    }
  }
  EXPECT_EQ(grid.heights(0, kHeight - 1), 1.5);  // the top-left pixel is white
}

TEST(HeightMapLoader, SixteenBitPngRoundTrip) {
  TempFile png("hills16.png"), yaml("hills16.yaml");
  writePng(png.path(), true);
  yaml.write(description("image", png.name()));
  const config::LoadedHeightMap map = config::loadHeightMap(yaml.path());
  expectImageLayout(map, 65535);
  EXPECT_TRUE(map.warnings.empty());
  EXPECT_EQ(map.smoothing, 0.0);
  EXPECT_EQ(map.grid.source, png.path());
}

TEST(HeightMapLoader, EightBitPngIsSmoothedWithAWarning) {
  TempFile png("coarse8.png"), yaml("coarse8.yaml"), raw_yaml("coarse8_raw.yaml");
  writePng(png.path(), false);
  yaml.write(description("image", png.name()));
  const config::LoadedHeightMap map = config::loadHeightMap(yaml.path());
  ASSERT_EQ(map.warnings.size(), 2u);
  EXPECT_NE(map.warnings[0].find("256 grey levels: one is 0.00784"), std::string::npos)
      << map.warnings[0];
  EXPECT_NE(map.warnings[1].find("sigma 2 pixels"), std::string::npos) << map.warnings[1];
  EXPECT_EQ(map.smoothing, config::kEightBitSmoothing);
  // smoothing: 0 keeps the levels, and the warnings.
  raw_yaml.write(description("image", png.name(), "min_height: -0.5\nmax_height: 1.5\nsmoothing: 0\n"));
  const config::LoadedHeightMap raw = config::loadHeightMap(raw_yaml.path());
  expectImageLayout(raw, 255);
  EXPECT_EQ(raw.warnings.size(), 2u);
  EXPECT_GT((map.grid.heights - raw.grid.heights).cwiseAbs().maxCoeff(), 0.01);
}

std::string pgm(unsigned max_level, const std::string& header_comment = "") {
  std::string bytes = "P5\n" + header_comment + std::to_string(kWidth) + " " +
                      std::to_string(kHeight) + "\n" + std::to_string(max_level) + "\n";
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) {
      const unsigned grey = level(r, c, max_level);
      if (max_level > 255) bytes.push_back(static_cast<char>(grey >> 8));
      bytes.push_back(static_cast<char>(grey & 0xff));
    }
  }
  return bytes;
}

TEST(HeightMapLoader, PgmRoundTripAndBadSamples) {
  TempFile image("map.pgm"), yaml("pgm.yaml");
  yaml.write(description("image", image.name()));
  image.write(pgm(65535, "# a comment\n"));
  expectImageLayout(config::loadHeightMap(yaml.path()), 65535);
  image.write(pgm(1000));
  expectImageLayout(config::loadHeightMap(yaml.path()), 1000);
  std::string above = pgm(1000);
  const std::size_t samples = above.size() - 2 * kWidth * kHeight;
  above[samples + 2 * (3 * kWidth + 4)] = static_cast<char>(0x0f);  // row 3, column 4: > 3840
  image.write(above);
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), image.path(), "row 3, column 4",
                          "above maxval 1000");
  image.write(pgm(1000).substr(0, 40));
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), image.path(), "after 13 of 108 samples");
  image.write("P2\n12 9\n255\n0 0 0");
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), image.path(), "P2", "P5");
}

// fuzz_read_pgm's finding (test/fuzz/corpus/fuzz_read_pgm/huge_header.pgm): the header's size
// was allocated before the file was seen to be shorter, so a corrupt header of a few bytes asked
// for gigabytes (here 2 TiB: std::bad_alloc, or the process killed for its memory).
TEST(HeightMapLoader, APgmHeaderLargerThanItsFileIsRefusedWithoutAllocatingIt) {
  TempFile image("huge.pgm");
  image.write(std::string("P5\n1048576 1048576\n65535\n") + std::string(5, '\x01'));
  EXPECT_INVALID_ARGUMENT(config::readPgm(image.path()), image.path(),
                          "after 2 of 1099511627776 samples (1048576 x 1048576)");
}

TEST(HeightMapLoader, CsvRoundTripKeepsEveryDigit) {
  TempFile csv("grid.csv"), yaml("csv.yaml");
  std::ostringstream text;
  text << "# eq 59, a = 0.2 m, w = 2 rad/m; first line the +y edge\n" << std::setprecision(17);
  const auto eq59 = [](double x, double y) { return 0.2 * (std::cos(2 * x) + std::cos(2 * y) - 2); };
  for (int r = 0; r < kHeight; ++r) {
    for (int c = 0; c < kWidth; ++c) text << (c ? "," : "") << eq59(1.125 + 0.25 * c, -1.875 + 0.25 * (kHeight - 1 - r));
    text << "\r\n";
  }
  csv.write(text.str());
  yaml.write(description("csv", csv.name(), ""));
  const config::LoadedHeightMap map = config::loadHeightMap(yaml.path());
  for (int i = 0; i < kWidth; ++i)
    for (int j = 0; j < kHeight; ++j)
      EXPECT_EQ(map.grid.heights(i, j), eq59(1.125 + 0.25 * i, -1.875 + 0.25 * j));
  EXPECT_TRUE(map.warnings.empty());

  csv.write("1,2,3\n4,x,6\n");
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), csv.path(), "line 2, column 2", "'x'");
  csv.write("1,2,3\n\n4,5\n");
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), csv.path(), "line 3 has 2 cells",
                          "line 1 has 3");
  csv.write("1,2,3\n4,nan,6\n");
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), "line 2, column 2", "finite");
  csv.write("1,2,\n");
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), "line 1, column 3", "empty");
}

TEST(HeightMapLoader, DescriptionErrorsNameTheKeyAndTheLimit) {
  TempFile png("any.png"), yaml("bad.yaml");
  writePng(png.path(), true);
  const auto expect_error = [&](const std::string& text, std::initializer_list<const char*> words) {
    yaml.write(text);
    for (const char* word : words) {
      EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), yaml.path(), word) << text;
    }
  };
  expect_error("image: " + png.name() + "\norigin: [0, 0]\nmin_height: 0\nmax_height: 1\n",
               {"resolution", "missing"});
  expect_error(description("image", png.name()) + "resolutoin: 1\n", {"resolutoin", "resolution, origin"});
  expect_error(description("image", png.name()) + "csv: a.csv\n", {"exactly one"});
  expect_error("resolution: 1\norigin: [0, 0]\n", {"exactly one"});
  expect_error(description("csv", "a.csv"), {"min_height", "images only"});
  expect_error("image: " + png.name() + "\nresolution: 0.1\norigin: [0, 0, 0.5]\nmin_height: 0\nmax_height: 1\n",
               {"origin", "rotated"});
  expect_error(description("image", png.name(), "min_height: 1\nmax_height: 1\n"),
               {"max_height", "above min_height"});
  expect_error(description("image", png.name(), "min_height: 1\n"), {"max_height", "missing"});
  expect_error(description("image", "a.jpg"), {"a.jpg", ".png or .pgm"});
  expect_error(description("image", png.name(), "min_height: 0\nmax_height: 1\nsmoothing: -1\n"),
               {"smoothing", ">= 0"});
}

TEST(HeightMapLoader, PngErrorsSayWhatTheFileIs) {
  TempFile png("colour.png"), yaml("colour.yaml");
  yaml.write(description("image", png.name()));
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = 5;
  image.height = 5;
  image.format = PNG_FORMAT_RGB;
  const std::vector<std::uint8_t> pixels(5 * 5 * 3, 100);
  ASSERT_NE(png_image_write_to_file(&image, png.path().c_str(), 0, pixels.data(), 0, nullptr), 0);
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), png.path(), "8-bit RGB",
                          "8- or 16-bit grey");
  png.write("P5 not a png at all");
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), png.path(), "not a PNG");
  std::remove(png.path().c_str());
  EXPECT_INVALID_ARGUMENT(config::loadHeightMap(yaml.path()), png.path(), "cannot read");
  std::string truncated;
  {
    writePng(png.path(), true);
    std::ifstream in(png.path(), std::ios::binary);
    truncated.assign(std::istreambuf_iterator<char>(in), {});
  }
  png.write(truncated.substr(0, truncated.size() - 20));
  EXPECT_THROW(config::loadHeightMap(yaml.path()), std::invalid_argument);
}

TEST(MakeSurface, HeightMapFromTheTerrainConfig) {
  TempFile csv("flat.csv"), yaml("flat.yaml");
  std::string rows;
  for (int r = 0; r < 6; ++r) rows += "0.1,0.1,0.1,0.1,0.1,0.1\n";
  csv.write(rows);
  yaml.write(description("csv", csv.name(), ""));
  config::SurfaceSpec spec;
  spec.type = "height_map";
  spec.height_map = yaml.name();  // relative to the base directory
  config::SurfaceLoading loading;
  loading.base_directory = ::testing::TempDir();
  const auto surface = config::makeSurface(spec, loading);
  EXPECT_NEAR(surface->height(1.5, -1.0), 0.1, 1e-15);
  EXPECT_EQ(surface->domain()->min(), Eigen::Vector2d(1.125, -1.875));
  EXPECT_NE(surface->describe().find(csv.path()), std::string::npos) << surface->describe();
  spec.height_map.clear();
  EXPECT_INVALID_ARGUMENT(config::makeSurface(spec, loading), "height_map");
  spec.height_map = "missing.yaml";
  EXPECT_INVALID_ARGUMENT(config::makeSurface(spec, loading), "missing.yaml");

  // An 8-bit map's warnings reach the caller.
  TempFile png("warn8.png"), yaml8("warn8.yaml");
  writePng(png.path(), false);
  yaml8.write(description("image", png.name()));
  spec.height_map = yaml8.path();  // absolute: the base directory does not apply
  loading.base_directory = "/nonexistent";
  std::vector<std::string> warnings;
  loading.warn = [&](const std::string& warning) { warnings.push_back(warning); };
  EXPECT_NO_THROW(config::makeSurface(spec, loading));
  EXPECT_EQ(warnings.size(), 2u);
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
