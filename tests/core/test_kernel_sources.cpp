// The model's single-source kernels (core/model/kernels/*.glsl, issue 15) stay inside the subset of
// GLSL 3.30 that C++ compiles the same way (core/model/glsl_compat.hpp). Both compilers already refuse
// most departures; these are the ones that would compile on both sides and silently differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::filesystem::path kKernelDir = KERF_MODEL_KERNELS_DIR;

std::vector<std::filesystem::path> sharedKernelFiles() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(kKernelDir)) {
    // The prelude is the GLSL half of the compatibility layer; it is not included by C++.
    if (entry.path().extension() == ".glsl" && entry.path().filename() != "glsl_prelude.glsl")
      files.push_back(entry.path());
  }
  return files;
}

// The code of a line without its // comment.
std::string codeOf(const std::string& line) {
  const auto comment = line.find("//");
  return comment == std::string::npos ? line : line.substr(0, comment);
}

TEST(KernelSources, FloatLiteralsCarryAnFSuffix) {
  // In C++ an unsuffixed 0.5 is a double: the CPU would compute that expression in double while the
  // GPU computes it in float, and the two back-ends drift apart.
  const std::regex unsuffixed(R"((^|[^\w.])((\d+\.\d*|\.\d+)([eE][-+]?\d+)?|\d+[eE][-+]?\d+)(?![\w.]))");
  ASSERT_FALSE(sharedKernelFiles().empty()) << "no kernels found in " << kKernelDir;
  for (const auto& file : sharedKernelFiles()) {
    std::ifstream in(file);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const std::string code = codeOf(line);
      std::smatch match;
      EXPECT_FALSE(std::regex_search(code, match, unsuffixed))
          << file.filename() << ":" << number << ": literal '" << match.str(2) << "' needs an f suffix";
    }
  }
}

TEST(KernelSources, NoPreprocessorLines) {
  // C++ includes each kernel file inside a struct body; a directive there would act on the whole TU.
  for (const auto& file : sharedKernelFiles()) {
    std::ifstream in(file);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const auto first = line.find_first_not_of(" \t");
      EXPECT_FALSE(first != std::string::npos && line[first] == '#')
          << file.filename() << ":" << number << ": preprocessor line in a shared kernel";
    }
  }
}

TEST(KernelSources, NoFunctionIsDefinedTwice) {
  // GLSL resolves overloads by exact types, C++ by conversions: an int and a float overload of one name
  // can pick different functions on the two back-ends.
  const std::regex definition(
      R"(^(float|int|uint|bool|vec[234]|ivec[234]|mat3|WoodSample|void)\s+(\w+)\s*\()");
  std::vector<std::string> names;
  for (const auto& file : sharedKernelFiles()) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
      std::smatch match;
      if (std::regex_search(line, match, definition)) names.push_back(match.str(2));
    }
  }
  ASSERT_GT(names.size(), 10u);
  std::sort(names.begin(), names.end());
  const auto twice = std::adjacent_find(names.begin(), names.end());
  EXPECT_EQ(twice, names.end()) << "defined twice: " << *twice;
}

}  // namespace
