#include "io/png_codec.hpp"

#include <png.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <utility>

#include "util/error.hpp"
#include "util/size_limits.hpp"

namespace kerf {
namespace {

// libpng reports errors by longjmp. Each function below that calls libpng sets its jump point first and
// creates no object with a destructor after it, so a jump skips no destructor; the message is copied into
// a state that outlives the jump.
struct PngState {
  char message[256] = "unknown error";
};

void onError(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message ? message : "unknown error");
  png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}  // unknown chunks, odd colour profiles: no failure

constexpr bool kLittleEndian = std::endian::native == std::endian::little;
// zlib level 2 and the "up" filter on every row. Measured on a 1200 x 1200 board render (one core,
// busy machine): 27 ms and 590 kB, against 154 ms and 443 kB at libpng's defaults (level 6, every filter
// tried per row), which OpenImageIO used; on a CN03 photo 140 kB either way. Renders are written far
// more often than they are archived.
constexpr int kCompressionLevel = 2;

class CFile {  // closed on every way out
 public:
  CFile(const std::filesystem::path& path, const char* mode) : file_(std::fopen(path.c_str(), mode)) {}
  ~CFile() {
    if (file_) std::fclose(file_);
  }
  CFile(CFile&& other) noexcept : file_(std::exchange(other.file_, nullptr)) {}
  CFile(const CFile&) = delete;
  CFile& operator=(const CFile&) = delete;
  FILE* get() const { return file_; }
  bool close() {
    const bool ok = file_ && std::fclose(file_) == 0;
    file_ = nullptr;
    return ok;
  }

 private:
  FILE* file_;
};

struct Reader {
  PngState state;
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &state, onError, onWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  Reader() {
    if (!png || !info) throw std::bad_alloc();
  }
  ~Reader() { png_destroy_read_struct(&png, &info, nullptr); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;
};

struct Writer {
  PngState state;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, onError, onWarning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  Writer() {
    if (!png || !info) throw std::bad_alloc();
  }
  ~Writer() { png_destroy_write_struct(&png, &info); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
};

CFile openForReading(const std::filesystem::path& path) {
  CFile file(path, "rb");
  if (!file.get()) throw InputError("cannot read image " + path.string() + ": " + std::strerror(errno));
  return file;
}

struct Decoding {
  PngHeader header;
  std::size_t rowBytes = 0;
  int passes = 1;  // 7 for interlaced files
};

// Reads the header and asks for 8- or 16-bit grey, grey + alpha, RGB or RGBA, native byte order.
bool startDecoding(Reader& r, FILE* file, Decoding& d) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_init_io(r.png, file);
  png_read_info(r.png, r.info);
  png_set_expand(r.png);  // palette -> RGB(A), grey below 8 bits -> 8, tRNS -> alpha
  if (kLittleEndian && png_get_bit_depth(r.png, r.info) == 16) png_set_swap(r.png);
  d.passes = png_set_interlace_handling(r.png);
  png_read_update_info(r.png, r.info);
  d.header.width = static_cast<int>(png_get_image_width(r.png, r.info));
  d.header.height = static_cast<int>(png_get_image_height(r.png, r.info));
  d.header.channels = png_get_channels(r.png, r.info);
  d.header.bits = png_get_bit_depth(r.png, r.info);
  d.rowBytes = png_get_rowbytes(r.png, r.info);
  return true;
}

// One decoded row to floats with `outChannels` per pixel (grey replicated, alpha dropped when fewer).
void convertRow(const unsigned char* row, const PngHeader& h, float* to, int outChannels) {
  const int from = h.channels;
  for (int x = 0; x < h.width; ++x)
    for (int c = 0; c < outChannels; ++c) {
      const int source = x * from + (outChannels == from || from >= 3 ? c : 0);
      float value;
      if (h.bits == 16) {
        std::uint16_t v;
        std::memcpy(&v, row + 2 * source, 2);
        value = static_cast<float>(v) * (1.0f / 65535.0f);
      } else {
        value = static_cast<float>(row[source]) * (1.0f / 255.0f);
      }
      to[x * outChannels + c] = value;
    }
}

bool decodeRows(Reader& r, const Decoding& d, unsigned char* row, png_bytepp wholeImage, float* out,
                int outChannels) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  const std::size_t stride = static_cast<std::size_t>(d.header.width) * outChannels;
  if (wholeImage) {  // interlaced: every pass touches every row
    png_read_image(r.png, wholeImage);
    for (int y = 0; y < d.header.height; ++y)
      convertRow(wholeImage[y], d.header, out + y * stride, outChannels);
  } else {
    for (int y = 0; y < d.header.height; ++y) {
      png_read_row(r.png, row, nullptr);
      convertRow(row, d.header, out + y * stride, outChannels);
    }
  }
  return true;
}

Decoding startOrThrow(Reader& r, FILE* file, const std::filesystem::path& path) {
  Decoding d;
  if (!startDecoding(r, file, d))
    throw InputError("cannot read image " + path.string() + ": " + r.state.message);
  return d;
}

// Quantises row y of `image` as OpenImageIO does (v * max + 0.5, clamped, truncated; NaN -> 0).
void quantizeRow(const Image& image, int y, int bits, unsigned char* to) {
  const float* from = image.pixel(0, y);
  const std::size_t count = static_cast<std::size_t>(image.width) * image.channels;
  const float max = bits == 16 ? 65535.0f : 255.0f;
  for (std::size_t i = 0; i < count; ++i) {
    const float scaled = from[i] * max + 0.5f;
    const float v = scaled > 0.0f ? std::min(scaled, max) : 0.0f;
    if (bits == 16) {
      const auto q = static_cast<std::uint16_t>(v);
      std::memcpy(to + 2 * i, &q, 2);
    } else {
      to[i] = static_cast<unsigned char>(v);
    }
  }
}

bool encode(Writer& w, const Image& image, const PngWriteOptions& o, png_textp texts, int textCount,
            unsigned char* row) {
  if (setjmp(png_jmpbuf(w.png))) return false;
  static constexpr int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA, PNG_COLOR_TYPE_RGB,
                                         PNG_COLOR_TYPE_RGB_ALPHA};
  png_set_IHDR(w.png, w.info, static_cast<png_uint_32>(image.width), static_cast<png_uint_32>(image.height),
               o.bits, kColourTypes[image.channels - 1], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_set_compression_level(w.png, kCompressionLevel);
  png_set_filter(w.png, PNG_FILTER_TYPE_BASE, PNG_FILTER_UP);
  if (o.pxPerMm > 0.0f) {
    const auto perMetre = static_cast<png_uint_32>(std::lround(o.pxPerMm * 1000.0f));
    png_set_pHYs(w.png, w.info, perMetre, perMetre, PNG_RESOLUTION_METER);
  }
  if (textCount > 0) png_set_text(w.png, w.info, texts, textCount);
  png_write_info(w.png, w.info);
  if (o.bits == 16 && kLittleEndian) png_set_swap(w.png);
  for (int y = 0; y < image.height; ++y) {
    quantizeRow(image, y, o.bits, row);
    png_write_row(w.png, row);
  }
  png_write_end(w.png, w.info);
  return true;
}

void checkWritable(const Image& image, const PngWriteOptions& o, const std::string& name) {
  if (image.empty() || image.width <= 0 || image.height <= 0)
    throw InputError("refusing to write an empty image to " + name);
  if (image.channels < 1 || image.channels > 4)
    throw InputError("cannot write " + name + ": PNG holds 1 to 4 channels, the image has " +
                     std::to_string(image.channels));
  if (o.bits != 8 && o.bits != 16)
    throw InputError("cannot write " + name + ": PNG is written with 8 or 16 bits");
}

// Encodes through `w`, whose output the caller has set.
void encodeOrThrow(Writer& w, const Image& image, const PngWriteOptions& o, const std::string& name) {
  checkWritable(image, o, name);
  std::vector<PngText> strings = o.text;  // libpng wants non-const chars
  std::vector<png_text> texts(strings.size());
  for (std::size_t i = 0; i < strings.size(); ++i) {
    texts[i].compression = PNG_TEXT_COMPRESSION_NONE;
    texts[i].key = strings[i].key.data();
    texts[i].text = strings[i].value.data();
    texts[i].text_length = strings[i].value.size();
  }
  std::vector<unsigned char> row(static_cast<std::size_t>(image.width) * image.channels * (o.bits / 8));
  if (!encode(w, image, o, texts.data(), static_cast<int>(texts.size()), row.data()))
    throw InputError("cannot write " + name + ": " + w.state.message);
}

void appendBytes(png_structp png, png_bytep data, png_size_t size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
  bool ok = true;
  try {
    bytes->insert(bytes->end(), data, data + size);
  } catch (...) {
    ok = false;
  }
  if (!ok) png_error(png, "out of memory");
}
void noFlush(png_structp) {}

bool readInfoChunks(Reader& r, FILE* file, PngInfo& info, png_textp* texts, int* textCount) {
  if (setjmp(png_jmpbuf(r.png))) return false;
  png_init_io(r.png, file);
  png_read_info(r.png, r.info);
  info.header.width = static_cast<int>(png_get_image_width(r.png, r.info));
  info.header.height = static_cast<int>(png_get_image_height(r.png, r.info));
  info.header.channels = png_get_channels(r.png, r.info);
  info.header.bits = png_get_bit_depth(r.png, r.info);
  png_uint_32 x = 0, y = 0;
  int unit = 0;
  if (png_get_pHYs(r.png, r.info, &x, &y, &unit) && unit == PNG_RESOLUTION_METER)
    info.pixelsPerMetre = static_cast<float>(x);
  *textCount = png_get_text(r.png, r.info, texts, nullptr);
  return true;
}

}  // namespace

bool hasPngSignature(const std::filesystem::path& path) {
  CFile file(path, "rb");
  unsigned char signature[8] = {};
  return file.get() && std::fread(signature, 1, 8, file.get()) == 8 && png_sig_cmp(signature, 0, 8) == 0;
}

PngHeader readPngHeader(const std::filesystem::path& path) {
  CFile file = openForReading(path);
  Reader r;
  return startOrThrow(r, file.get(), path).header;
}

void readPngPixels(const std::filesystem::path& path, Image& out) {
  CFile file = openForReading(path);
  Reader r;
  const Decoding d = startOrThrow(r, file.get(), path);
  if (out.width != d.header.width || out.height != d.header.height ||
      (out.channels != d.header.channels && out.channels != 3))
    throw InputError("cannot decode image " + path.string() + ": it changed while being read");
  std::vector<unsigned char> buffer, row;
  std::vector<png_bytep> rows;
  if (d.passes > 1) {
    checkMemoryNeed(d.rowBytes * d.header.height, "the interlaced PNG " + path.string());
    buffer.resize(d.rowBytes * d.header.height);
    for (int y = 0; y < d.header.height; ++y) rows.push_back(buffer.data() + y * d.rowBytes);
  } else {
    row.resize(d.rowBytes);
  }
  if (!decodeRows(r, d, row.data(), rows.empty() ? nullptr : rows.data(), out.pixels.data(), out.channels))
    throw InputError("cannot decode image " + path.string() + ": " + r.state.message);
}

void writePngFile(const std::filesystem::path& path, const Image& image, const PngWriteOptions& options,
                  const std::filesystem::path& target) {
  const std::string name = (target.empty() ? path : target).string();
  checkWritable(image, options, name);
  CFile file(path, "wb");
  if (!file.get()) throw InputError("cannot write " + name + ": " + std::strerror(errno));
  Writer w;
  png_init_io(w.png, file.get());
  encodeOrThrow(w, image, options, name);
  if (std::fflush(file.get()) != 0 || std::ferror(file.get()) || !file.close())
    throw InputError("cannot write " + name +
                     ": the file could not be written completely (is the disk full?)");
}

std::vector<unsigned char> encodePngBytes(const Image& image, const PngWriteOptions& options) {
  std::vector<unsigned char> bytes;
  Writer w;
  png_set_write_fn(w.png, &bytes, appendBytes, noFlush);
  encodeOrThrow(w, image, options, "a PNG in memory");
  return bytes;
}

PngInfo readPngInfo(const std::filesystem::path& path) {
  CFile file = openForReading(path);
  Reader r;
  PngInfo info;
  png_textp texts = nullptr;
  int count = 0;
  if (!readInfoChunks(r, file.get(), info, &texts, &count))
    throw InputError("cannot read image " + path.string() + ": " + r.state.message);
  for (int i = 0; i < count; ++i)
    info.text.push_back({texts[i].key, std::string(texts[i].text, texts[i].text_length)});
  return info;
}

}  // namespace kerf
