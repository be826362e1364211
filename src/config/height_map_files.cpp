#include "spherical_robots/config/height_map_files.hpp"

#include <png.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "spherical_robots/config/csv_lines.hpp"

namespace spherical_robots::config {
namespace {

std::invalid_argument fileError(const std::string& path, const std::string& what) {
  return std::invalid_argument(path + ": " + what);
}

// libpng reports errors by longjmp to the setjmp of the function that called it. Both functions
// that call into it below therefore create no object with a destructor after their setjmp, and
// the error text goes to a plain buffer.
struct PngErrorText {
  char text[256] = "";
};

void onPngError(png_structp png, png_const_charp message) {
  auto* error = static_cast<PngErrorText*>(png_get_error_ptr(png));
  std::snprintf(error->text, sizeof error->text, "%s", message);
  png_longjmp(png, 1);
}

void onPngWarning(png_structp, png_const_charp) {}  // ancillary-chunk complaints: not ours

/// libpng's read and info structures, released however the reading ends.
struct PngReader {
  png_structp png = nullptr;
  png_infop info = nullptr;
  explicit PngReader(PngErrorText& error)
      : png(png_create_read_struct(PNG_LIBPNG_VER_STRING, &error, &onPngError, &onPngWarning)),
        info(png ? png_create_info_struct(png) : nullptr) {
    if (!png || !info) {
      png_destroy_read_struct(&png, &info, nullptr);
      throw std::bad_alloc();
    }
  }
  ~PngReader() { png_destroy_read_struct(&png, &info, nullptr); }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
};

struct PngHeader {
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
};

bool readPngHeader(png_structp png, png_infop info, std::FILE* file, PngHeader& header) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_read_info(png, info);
  png_get_IHDR(png, info, &header.width, &header.height, &header.bit_depth, &header.colour_type,
               nullptr, nullptr, nullptr);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  return true;
}

bool readPngRows(png_structp png, png_infop info, png_bytepp rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_read_image(png, rows);
  png_read_end(png, info);
  return true;
}

std::string colourTypeName(int colour_type) {
  switch (colour_type) {
    case PNG_COLOR_TYPE_GRAY: return "grey";
    case PNG_COLOR_TYPE_GRAY_ALPHA: return "grey with alpha";
    case PNG_COLOR_TYPE_PALETTE: return "palette";
    case PNG_COLOR_TYPE_RGB: return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
    default: return "colour type " + std::to_string(colour_type);
  }
}

/// Reads whitespace- and comment-separated header fields of a PGM.
class PgmHeader {
 public:
  PgmHeader(std::istream& in, const std::string& path) : in_(in), path_(path) {}
  std::string token() {
    std::string field;
    while (field.empty()) {
      const int next = in_.get();
      if (next == EOF) throw fileError(path_, "PGM header ends early");
      if (next == '#') {
        std::string comment;
        std::getline(in_, comment);
      } else if (!std::isspace(next)) {
        field.push_back(static_cast<char>(next));
        while (in_.peek() != EOF && !std::isspace(in_.peek()) && in_.peek() != '#')
          field.push_back(static_cast<char>(in_.get()));
      }
    }
    return field;
  }
  unsigned number(const char* what, unsigned maximum) {
    const std::string field = token();
    char* end = nullptr;
    errno = 0;
    const unsigned long value = std::strtoul(field.c_str(), &end, 10);
    if (*end != '\0' || errno != 0 || value < 1 || value > maximum) {
      throw fileError(path_, std::string("PGM ") + what + " '" + field + "' must be 1 .. " +
                                 std::to_string(maximum));
    }
    return static_cast<unsigned>(value);
  }

 private:
  std::istream& in_;
  const std::string& path_;
};

}  // namespace

GreyImage readPng(const std::string& path) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                             &std::fclose);
  if (!file) throw fileError(path, std::string("cannot read: ") + std::strerror(errno));
  unsigned char signature[8] = {};
  if (std::fread(signature, 1, sizeof signature, file.get()) != sizeof signature ||
      png_sig_cmp(signature, 0, sizeof signature) != 0) {
    throw fileError(path, "not a PNG file");
  }
  PngErrorText error;
  PngReader reader(error);
  png_structp png = reader.png;
  png_infop info = reader.info;
  png_set_sig_bytes(png, sizeof signature);
  PngHeader header;
  if (!readPngHeader(png, info, file.get(), header)) throw fileError(path, error.text);
  if (header.colour_type != PNG_COLOR_TYPE_GRAY ||
      (header.bit_depth != 8 && header.bit_depth != 16)) {
    throw fileError(path, std::to_string(header.bit_depth) + "-bit " +
                              colourTypeName(header.colour_type) +
                              " PNG; a height map is an 8- or 16-bit grey PNG");
  }
  const std::size_t bytes = static_cast<std::size_t>(header.bit_depth / 8);
  std::vector<png_byte> pixels(static_cast<std::size_t>(header.width) * header.height * bytes);
  std::vector<png_bytep> rows(header.height);
  for (png_uint_32 r = 0; r < header.height; ++r)
    rows[r] = pixels.data() + static_cast<std::size_t>(r) * header.width * bytes;
  if (!readPngRows(png, info, rows.data())) throw fileError(path, error.text);
  GreyImage image;
  image.max_level = (1u << header.bit_depth) - 1u;
  image.levels.resize(header.height, header.width);
  for (png_uint_32 r = 0; r < header.height; ++r) {
    for (png_uint_32 c = 0; c < header.width; ++c) {
      const png_byte* sample = rows[r] + static_cast<std::size_t>(c) * bytes;
      // PNG stores 16-bit samples most significant byte first.
      image.levels(r, c) = static_cast<std::uint16_t>(bytes == 2 ? (sample[0] << 8) | sample[1] : sample[0]);
    }
  }
  return image;
}

GreyImage readPgm(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw fileError(path, std::string("cannot read: ") + std::strerror(errno));
  PgmHeader header(in, path);
  const std::string magic = header.token();
  if (magic != "P5") {
    throw fileError(path, "not a binary PGM (magic '" + magic + "', expected P5)");
  }
  const unsigned width = header.number("width", 1u << 20);
  const unsigned height = header.number("height", 1u << 20);
  GreyImage image;
  image.max_level = header.number("maxval", 65535);
  in.get();  // the single whitespace character between maxval and the samples
  const std::size_t bytes = image.max_level > 255 ? 2 : 1;
  const std::size_t samples = static_cast<std::size_t>(width) * height;
  // The file's length is checked before the header's size is allocated: a corrupt header may
  // promise gigabytes (2^20 x 2^20 samples) in a file of a few bytes.
  const std::streampos data_start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff available = in.tellg() - data_start;
  in.seekg(data_start);
  std::vector<unsigned char> data;
  if (in && available >= 0 && static_cast<std::size_t>(available) >= samples * bytes) {
    data.resize(samples * bytes);
    in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(data.size()));
  }
  if (data.empty() || static_cast<std::size_t>(in.gcount()) != data.size()) {
    const std::streamoff read = std::max<std::streamoff>(data.empty() ? available : in.gcount(), 0);
    throw fileError(path, "PGM data ends after " + std::to_string(read / static_cast<std::streamoff>(bytes)) +
                              " of " + std::to_string(samples) + " samples (" +
                              std::to_string(width) + " x " + std::to_string(height) + ")");
  }
  image.levels.resize(height, width);
  for (unsigned r = 0; r < height; ++r) {
    for (unsigned c = 0; c < width; ++c) {
      const unsigned char* sample = data.data() + (static_cast<std::size_t>(r) * width + c) * bytes;
      const unsigned level = bytes == 2 ? (sample[0] << 8) | sample[1] : sample[0];
      if (level > image.max_level) {
        throw fileError(path, "pixel (row " + std::to_string(r) + ", column " + std::to_string(c) +
                                  ") is " + std::to_string(level) + ", above maxval " +
                                  std::to_string(image.max_level));
      }
      image.levels(r, c) = static_cast<std::uint16_t>(level);
    }
  }
  return image;
}

Eigen::MatrixXd readCsvGrid(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw fileError(path, std::string("cannot read: ") + std::strerror(errno));
  std::vector<std::vector<double>> rows;
  int first_line = 0;
  for (const CsvLine& line : readCsvLines(in)) {
    std::vector<double> row;
    for (const std::string& cell : line.cells) {
      const std::optional<double> value = csvNumber(cell);
      if (!value || !std::isfinite(*value)) {
        throw fileError(path, "line " + std::to_string(line.number) + ", column " +
                                  std::to_string(row.size() + 1) + ": " +
                                  (cell.empty() ? std::string("empty cell")
                                                : "'" + cell + "' is not a finite number"));
      }
      row.push_back(*value);
    }
    if (rows.empty()) {
      first_line = line.number;
    } else if (row.size() != rows.front().size()) {
      throw fileError(path, "line " + std::to_string(line.number) + " has " +
                                std::to_string(row.size()) + " cells, line " +
                                std::to_string(first_line) + " has " +
                                std::to_string(rows.front().size()));
    }
    rows.push_back(std::move(row));
  }
  if (rows.empty()) throw fileError(path, "no rows of heights");
  Eigen::MatrixXd grid(static_cast<Eigen::Index>(rows.size()),
                       static_cast<Eigen::Index>(rows.front().size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    for (std::size_t c = 0; c < rows[r].size(); ++c)
      grid(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = rows[r][c];
  }
  return grid;
}

}  // namespace spherical_robots::config
