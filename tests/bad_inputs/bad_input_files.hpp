#pragma once
// Makers of bad input files for the catalogue (test_bad_inputs.cpp): each writes a small file (a few KB
// at most) that is broken in one precise way. Nothing here is checked in; every file is made by the test.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "io/image.hpp"
#include "util/error.hpp"

namespace kerf::bad {

namespace fs = std::filesystem;

// The message of the InputError `run` throws, or "" when it throws none (anything else fails the test).
// An empty folder for the running test: KERF_TEST_ARTIFACTS/suite/test name (with `sub` inside, when
// given), emptied first so that no earlier run's files count.
inline fs::path freshTestFolder(const std::string& suite, const std::string& sub = "") {
  const fs::path dir =
      fs::path(KERF_TEST_ARTIFACTS) / suite / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::remove_all(dir);
  fs::create_directories(sub.empty() ? dir : dir / sub);
  return dir;
}

inline std::string errorOf(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

inline void writeText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Keeps the first `fraction` of the file, as an interrupted copy or download does.
inline void truncateFile(const fs::path& path, double fraction) {
  const std::string bytes = readBytes(path);
  writeText(path, bytes.substr(0, static_cast<std::size_t>(bytes.size() * fraction)));
}

// The file's first `keep` bytes (its signature), then bytes that are no image data at all.
inline void corruptAfter(const fs::path& path, std::size_t keep) {
  std::string bytes = readBytes(path).substr(0, keep);
  for (int i = 0; i < 600; ++i) bytes.push_back(static_cast<char>((i * 37 + 11) & 0xff));
  writeText(path, bytes);
}

// A grey-ish RGB photo of w x h pixels.
inline void writePhoto(const fs::path& path, int w, int h, int channels = 3, int bits = 8) {
  Image image(w, h, channels);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = 0.25f + 0.5f * ((i / 3) % 7) / 7.0f;
  writeImage(path, image, bits);
}

// Six 16 x 16 face photos of a 40 mm cube: a valid sample folder to break one file of.
inline void writeSample(const fs::path& dir) {
  for (const char* face : {"A", "B", "C", "D", "E", "F"})
    writePhoto(dir / (std::string(face) + "_col.png"), 16, 16);
}

inline std::uint32_t crc32(const std::string& bytes) {
  std::uint32_t crc = 0xffffffffu;
  for (unsigned char c : bytes) {
    crc ^= c;
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

inline std::string bigEndian(std::uint32_t v) {
  return {static_cast<char>(v >> 24), static_cast<char>(v >> 16), static_cast<char>(v >> 8),
          static_cast<char>(v)};
}

inline std::string pngChunk(const std::string& type, const std::string& data) {
  return bigEndian(static_cast<std::uint32_t>(data.size())) + type + data + bigEndian(crc32(type + data));
}

// A valid PNG header (correct CRCs) that claims width x height RGB pixels, with almost no pixel data:
// 60 bytes that would take gigabytes if a reader believed them before decoding.
inline void writePngClaiming(const fs::path& path, std::uint32_t width, std::uint32_t height) {
  const std::string ihdr = bigEndian(width) + bigEndian(height) + std::string("\x08\x02\x00\x00\x00", 5);
  // An empty zlib stream: the decoder runs out of data on the first row.
  const std::string idat("\x78\x9c\x03\x00\x00\x00\x00\x01", 8);
  writeText(path, std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + pngChunk("IDAT", idat) +
                      pngChunk("IEND", ""));
}

}  // namespace kerf::bad
